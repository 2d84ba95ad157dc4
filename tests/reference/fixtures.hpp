// Hand-built variants and shadow maps for the reference tests.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "penumbra/compiler/model.hpp"
#include "penumbra/support/image.hpp"

namespace penumbra::testing {

inline Disk make_disk(std::vector<Point2> points) {
  return Disk{"test", "hand", 0, std::move(points), 0.0};
}

inline Variant hard_variant() {
  return Variant{"hard", Technique::hard, {}, {}, {}, {}};
}

inline Variant grid_variant(int kernel) {
  VariantKeys keys;
  keys.kernel = kernel;
  return Variant{"pcf_grid", Technique::pcf_grid, keys, {}, {}, {}};
}

inline Variant poisson_variant(std::vector<Point2> points) {
  VariantKeys keys;
  keys.pcf_samples = int(points.size());
  return Variant{"pcf_poisson", Technique::pcf_poisson, keys, {}, make_disk(std::move(points)), {}};
}

inline Variant pcss_variant(std::vector<Point2> blocker, std::vector<Point2> pcf) {
  VariantKeys keys;
  keys.blocker_samples = int(blocker.size());
  keys.pcf_samples = int(pcf.size());
  return Variant{
      "pcss", Technique::pcss, keys, make_disk(std::move(blocker)), make_disk(std::move(pcf)), {}};
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

}  // namespace penumbra::testing
