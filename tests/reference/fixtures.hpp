// Hand-built variants and shadow maps for the reference tests.
#pragma once

#include <algorithm>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "penumbra/model/light.hpp"
#include "penumbra/model/model.hpp"
#include "penumbra/support/image.hpp"

namespace penumbra::testing {

inline Disk make_disk(std::vector<Point2> points) {
  return Disk{"test", "hand", 0, std::move(points), 0.0};
}

inline Variant hard_variant() {
  return Variant{"hard", Technique::hard, {}, {}, {}, {}, {}};
}

inline Variant grid_variant(int kernel) {
  VariantKeys keys;
  keys.kernel = kernel;
  return Variant{"pcf_grid", Technique::pcf_grid, keys, {}, {}, {}, {}};
}

inline Variant poisson_variant(std::vector<Point2> points) {
  VariantKeys keys;
  keys.pcf_samples = int(points.size());
  return Variant{
      "pcf_poisson", Technique::pcf_poisson, keys, {}, make_disk(std::move(points)), {}, {}};
}

inline Variant pcss_variant(std::vector<Point2> blocker, std::vector<Point2> pcf) {
  VariantKeys keys;
  keys.blocker_samples = int(blocker.size());
  keys.pcf_samples = int(pcf.size());
  return Variant{
      "pcss", Technique::pcss, keys, make_disk(std::move(blocker)), make_disk(std::move(pcf)), {},
      {}};
}

inline Variant minmax_pcf_variant(int kernel) {
  VariantKeys keys;
  keys.kernel = kernel;
  return Variant{"minmax_pcf", Technique::minmax_pcf, keys, {}, {}, {}, {}};
}

inline Variant backprojection_variant() {
  return Variant{"backprojection", Technique::backprojection, {}, {}, {}, {}, {}};
}

inline Variant bitmask_backprojection_variant(int light_bits) {
  VariantKeys keys;
  keys.light_bits = light_bits;
  return Variant{variant_name(Technique::bitmask_backprojection, keys),
                 Technique::bitmask_backprojection,
                 keys,
                 {},
                 {},
                 {},
                 {}};
}

// The back-projection tests' light: n = 1, Fw = 2, L = 0.5, so a texel's
// slopes are (u - 0.5) * 2, and from a receiver at z_r = 2 straight below the
// light a patch at z = 1 projects with g(1) = 1 * 2 / (2 - 1) = 2: texels
// 3..4 of 8 (slopes -0.25..0.25) cover the light's [-0.5, 0.5] exactly.
inline LightParams unit_backprojection_light() {
  LightParams light;
  light.near_plane = 1.0;
  light.frustum_width = 2.0;
  light.light_world_size = 0.5;
  return light;
}

inline Variant pcss_minmax_variant(std::vector<Point2> pcf) {
  VariantKeys keys;
  keys.pcf_samples = int(pcf.size());
  return Variant{
      "pcss_minmax", Technique::pcss_minmax, keys, {}, make_disk(std::move(pcf)), {}, {}};
}

// screen_blur with radius R and the 2R + 1 taps `weights` (hand-picked: the
// reference takes whatever the compiler baked).
inline Variant blur_variant(int radius, std::vector<float> weights, bool depth_aware = false) {
  VariantKeys keys;
  keys.blur_radius = radius;
  if (depth_aware) keys.depth_aware = true;
  return Variant{"screen_blur", Technique::screen_blur, keys, {}, {}, {}, std::move(weights)};
}

// The R = 2 binomial taps (1, 4, 6, 4, 1) / 16: exact in float, so sums
// over them are exact too.
inline std::vector<float> binomial5() {
  return {1.0f / 16, 4.0f / 16, 6.0f / 16, 4.0f / 16, 1.0f / 16};
}

// A W x H map: `near_depth` in columns i < split, `far_depth` from there on.
inline FloatImage column_split_map(int width, int height, int split, float near_depth,
                                   float far_depth) {
  FloatImage map(width, height, 1);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) map.at(i, j) = i < split ? near_depth : far_depth;
  }
  return map;
}

// A W x H map of depths drawn uniformly from [lo, hi), reproducibly.
inline FloatImage random_map(int width, int height, float lo, float hi, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<float> depth(lo, hi);
  FloatImage map(width, height, 1);
  for (float& d : map.data) d = depth(generator);
  return map;
}

// A W x H map at `far_depth` with `count` random rectangles of constant depth
// in [lo, hi) painted over it: flat regions and edges, like a rendered map.
inline FloatImage blocky_map(int width, int height, int count, float lo, float hi, float far_depth,
                             unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_int_distribution<int> x(0, width - 1), y(0, height - 1);
  std::uniform_real_distribution<float> depth(lo, hi);
  FloatImage map(width, height, 1, far_depth);
  for (int r = 0; r < count; ++r) {
    const int x0 = x(generator), x1 = x(generator), y0 = y(generator), y1 = y(generator);
    const float z = depth(generator);
    for (int j = std::min(y0, y1); j <= std::max(y0, y1); ++j) {
      for (int i = std::min(x0, x1); i <= std::max(x0, x1); ++i) map.at(i, j) = z;
    }
  }
  return map;
}

}  // namespace penumbra::testing
