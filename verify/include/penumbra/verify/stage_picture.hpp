// A picture of the report's stage drawn by an engine whose surface shaders
// call a variant's function form (docs/function-form.md): per pixel the
// light clip position the fragment called penumbra_visibility() with and
// what it returned, checked against the CPU reference evaluated on exactly
// those receivers and the engine's own shadow map. verify's function form
// check draws such pictures on its engines; tests/threejs has three.js
// draw them.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "penumbra/model/model.hpp"
#include "penumbra/reference/compare.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/shadow_map.hpp"
#include "penumbra/reference/stage.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra {

// Silhouette pixels may see another surface than the ray cast; no more.
inline constexpr double kMinCameraAgreement = 0.97;

// The engine's shadow map as the function form read it.
struct EngineMap {
  FloatImage stored;  // 1 channel, row j at v = (j + 0.5) / height, as sampled
  // The encoding of `stored`; none for linear z * depth_scale.
  std::optional<reference::EncodedDepth> encoded;
  double depth_scale = 1.0;  // of a linear map
};

struct StagePictureCheck {
  // The visibility against the reference evaluated on the receivers the
  // GPU called the function with, over the pixels whose 2x2 quad lies on
  // one face of the stage.
  reference::Comparison comparison;
  std::size_t surface_pixels = 0;  // those pixels, compared or ambiguous
  // Of the pixels where the camera's ray cast hits a surface, the fraction
  // whose GPU receiver is the ray cast's (within 1e-3 in u, v and z_r / z):
  // the camera, the light matrix and the rows agree with the reference's.
  double camera_agreement = 0.0;
  bool pass = false;  // comparison.pass and camera_agreement >= kMinCameraAgreement
};

// (u, v, z_r) from each pixel's light clip position (x, y, w in channels
// 0, 1 and `w_channel`), as the function form derives them: v = 0.5 +
// `v_sign` y / w (0.5 for the GL targets, -0.5 for Direct3D's), z_r = w.
// An `orthographic` light's w is 1, and `w_channel` holds z_r instead.
// A pixel no surface covers (that channel <= 0, the clear) gets a receiver
// at the light, which is lit.
FloatImage receivers_from_clip(const FloatImage& clip, int w_channel, double v_sign,
                               bool orthographic = false);

// The pixels of `receivers` (the stage seen through `view`'s pixels, row 0
// at the top) inside one face of the stage with the rest of their 2x2
// quad, the pixels a GPU takes screen derivatives over, as indices in
// row-major order. Elsewhere the GPU's derivatives extrapolate a face past
// its edge, and rasterization and the ray cast may see different surfaces.
// Under an orthographic (directional) light, boxes' sides are left out:
// they lie along its rays.
std::vector<std::size_t> face_pixels(const reference::Stage& stage,
                                     const reference::StageView& view, const FloatImage& receivers);

// The references one device thread's pictures of one (variant, target)
// pair were judged against, by their inputs byte for byte: the target's
// paths often draw pictures of the same receivers on the same map (the
// deferred pass's receivers are rebuilt on the CPU; every path that reads
// the prepared map reads the same texels), and the reference is most of
// what judging a picture costs. For one thread at a time.
class PictureReferences {
 public:
  // The reference at `receivers` on `map` for `variant` under `light`,
  // evaluated on the first call with inputs equal to these, copied after.
  Result<reference::ReferenceImage> get(const Variant& variant, const EngineMap& map,
                                        const LightParams& light, const FloatImage& receivers,
                                        const reference::SamplingPrecision& precision,
                                        const reference::ShaderLimits& limits);
  // How many distinct inputs it has evaluated.
  std::size_t evaluated() const { return entries_.size(); }

 private:
  struct Entry {
    std::string variant;
    LightParams light;
    int sub_texel_bits = 0;
    reference::ShaderLimits limits;
    std::optional<reference::EncodedDepth> encoded;
    double depth_scale = 1.0;
    FloatImage map;  // as stored
    FloatImage receivers;
    reference::ReferenceImage value;
  };
  std::vector<Entry> entries_;
};

// The same receivers as float32 shaders may compute them, where the GPU's
// own are not known exactly, each the receivers' size: made only when a
// check needs them, since most pictures match the reference without them.
using RoundedReceivers = std::function<std::vector<FloatImage>()>;

// `visibility` (channel `channel`), drawn by `variant`'s function form at
// `receivers` (the view's size) on `map` under `light`, against the reference.
// `rounded` makes the same receivers as float32 shaders may compute them, where
// the GPU's own are not known exactly: a pixel whose reference differs at one
// of them by over half the tolerance is ambiguous. A pixel ambiguous only for
// that reason or for depth ties (the reference's `low` and `high`) is compared
// with the nearest value of the reference's range over those alternatives where
// the GPU's value lies within the tolerance of it, and left out elsewhere. The
// alternatives are made and evaluated only where the GPU lies over a tenth of
// the tolerance from the reference at some pixel, and there only at those
// pixels: elsewhere they cannot change the outcome. With `references`, the
// reference comes from there. Errors: the reference's, for inputs it cannot
// evaluate.
Result<StagePictureCheck> check_stage_picture(
    const Variant& variant, const reference::Stage& stage, const reference::StageView& view,
    const EngineMap& map, const LightParams& light, const FloatImage& receivers,
    const FloatImage& visibility, int channel, const reference::SamplingPrecision& precision,
    const reference::ShaderLimits& limits, const RoundedReceivers& rounded = {},
    PictureReferences* references = nullptr);

}  // namespace penumbra
