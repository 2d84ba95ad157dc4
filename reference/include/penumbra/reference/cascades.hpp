// Cascaded shadow maps of a directional light (docs/techniques.md,
// "Cascades"): the camera's depth split into ranges, each shaded from an
// orthographic map fitted to its slice of the view frustum, the cascade
// chosen by view depth and blended into the next across a band. Here are
// the splits, the fit, the choice, and the deep stage the cascades are
// measured on.
#pragma once

#include <span>
#include <vector>

#include "penumbra/reference/stage.hpp"

namespace penumbra::reference {

// One cascade's orthographic map, in the stage's light-view space.
struct Cascade {
  double centre_x = 0.0;  // the map's centre (its uv 0.5, 0.5)
  double centre_y = 0.0;
  double width = 1.0;   // the map's side (Fw): uv = 0.5 + (x - centre_x) / width
  double near_z = 0.0;  // the depth range the map encodes (n, f)
  double far_z = 1.0;
  double split_far = 1.0;  // the view depth where the cascade's range ends

  bool operator==(const Cascade&) const = default;
};

// A directional light's stage deep enough for several cascades: a long
// ground, boxes near the camera and far from it, a camera looking along it.
// The scene's light is orthographic and its light_world_size the light's
// half-slope, tan of half its angular size (the same in every cascade).
struct CascadedStage {
  Stage stage;
  std::vector<Cascade> cascades;  // nearest first
  double view_near = 1.0;         // where the first cascade's range starts
  double blend_band = 0.1;        // the part of each range that fades into the next
  int map_size = 512;             // each cascade's map, map_size x map_size texels
  double filter_radius = 0.05;    // pcf_poisson's radius in light-view units, every cascade's

  bool operator==(const CascadedStage&) const = default;
};

// The ends of `count` ranges splitting [near, far]: the practical scheme
// (Zhang et al., "Parallel-Split Shadow Maps"), lambda mixing the
// logarithmic split (1) with the uniform one (0). `count` values, the last
// `far`.
std::vector<double> practical_splits(double near, double far, int count, double lambda);

// Cascades for the view depths (`view_near`, split_fars[0]], (split_fars[0],
// split_fars[1]], ...: each a square around the bounding sphere of its
// slice of the camera's frustum (a side that does not change as the camera
// turns), its centre snapped to whole texels of a `map_size` map, and
// every cascade encoding [near_z, far_z].
std::vector<Cascade> fit_cascades(const Stage& stage, int width, int height, double view_near,
                                  std::span<const double> split_fars, int map_size, double near_z,
                                  double far_z);

// The stage with 4 cascades (docs/verification.md, "The cascaded stage").
CascadedStage cascaded_stage();

// The stage's scene as cascade `c`'s map sees it: moved so that the
// cascade's centre is at x = y = 0, its light the directional light of that
// map (orthographic, Fw = width, n = near_z) with the scene's half-slope
// and bias and the stage's filter radius in that map's uv, its map
// map_size square, an empty texel at far_z. A point's exact visibility is
// the same in it as in the stage (the light is directional).
Scene cascade_scene(const CascadedStage& stage, std::size_t c);

// The whole stage as cascade `c`'s map sees it: cascade_scene() named
// "cascaded_stage, cascade c", with the camera and the ground moved with
// it, so that its view is the stage's, pixel for pixel, in that map's
// coordinates. What verify draws a cascade's call on.
Stage cascade_stage(const CascadedStage& stage, std::size_t c);

// Which cascades shade a point at view depth `depth`: `first`, and `next`
// with weight `next_weight` where the depth lies in the last `blend_band`
// of first's range (linear across it). first is -1 beyond the last
// cascade (lit), next -1 where nothing blends.
struct CascadeChoice {
  int first = -1;
  int next = -1;
  double next_weight = 0.0;
};
CascadeChoice choose_cascade(std::span<const Cascade> cascades, double view_near, double depth,
                             double blend_band);

// The view depth of each of `view`'s pixels: its point's distance along the
// camera's forward axis; infinity on the background.
std::vector<double> view_depths(const Stage& stage, const StageView& view);

}  // namespace penumbra::reference
