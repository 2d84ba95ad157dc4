// The CPU reference of a cascaded call over a camera's view: each pixel
// shaded from the cascade its view depth chooses, blended into the next
// across the band (choose_cascade()), each cascade's map the ray cast of
// its scene. What a cascaded variant's picture is checked against, and the
// seams between cascades measured on (docs/accuracy.md, "Cascades").
#pragma once

#include <span>
#include <vector>

#include "penumbra/reference/cascades.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {

struct CascadeMap {
  Scene scene;     // cascade_scene()
  FloatImage map;  // its ray-cast depth, linear z
};

// Every cascade's scene and map.
std::vector<CascadeMap> cascade_maps(const CascadedStage& stage);

// `maps` with each cascade's light size and pcf_poisson radius the
// nearest cascade's in uv, as a renderer with one size for every cascade
// (in texels or uv) has them: the comparison the seams are measured against.
std::vector<CascadeMap> sized_as_nearest(const CascadedStage& stage, std::vector<CascadeMap> maps);

// The receivers (u, v, z_r) of every pixel of `view` in `cascade`'s map;
// a background pixel's as in `view`.
FloatImage cascade_receivers(const StageView& view, const Cascade& cascade);

struct CascadedImage {
  FloatImage visibility;               // 1 channel: the blended result
  std::vector<CascadeChoice> choices;  // per pixel
  // Per cascade, 1 channel: its visibility at the pixels that read it
  // (first or next), 0 elsewhere.
  std::vector<FloatImage> cascades;
};

// `variant` (a technique that reads the map alone) over `view` of
// `stage`, with `maps` from cascade_maps(). Errors: as evaluate_visibility().
Result<CascadedImage> evaluate_cascaded(const Variant& variant, const CascadedStage& stage,
                                        const StageView& view, std::span<const CascadeMap> maps,
                                        const ShaderLimits& limits = {});

// The jump a cascade boundary would show without blending: over the
// pixels of `region` (true where measured) that read both cascades of
// a boundary, |visibility in one - in the other|.
struct SeamFigures {
  std::size_t pixels = 0;
  double mean = 0.0;
  double max = 0.0;
};
// One per boundary: [c] between cascades c and c + 1.
std::vector<SeamFigures> seam_jumps(const CascadedImage& image, const std::vector<bool>& region);

}  // namespace penumbra::reference
