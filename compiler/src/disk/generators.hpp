// The generator methods behind generate_disk and what they share.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "penumbra/model/model.hpp"

namespace penumbra::disk_detail {

// Uniform random points in the unit disk, the same on every platform: raw
// std::mt19937_64 output (fully specified by the standard) turned into doubles
// with integer arithmetic, never a distribution (implementation-defined).
class UnitDiskSampler {
 public:
  explicit UnitDiskSampler(std::uint64_t seed) : engine_(seed) {}

  // A float32 point whose distance from the origin is at most 1.
  Point2 next();
  double next_unit();  // uniform in [0, 1), a multiple of 2^-53

 private:
  std::mt19937_64 engine_;
};

// Squared distance computed in double from the float32 coordinates.
double squared_distance(const Point2& a, const Point2& b);

// The hexagonal-packing bound on the minimum distance of `count` points in
// the unit disk: sqrt(2 pi / (sqrt(3) count)).
double hexagonal_distance_bound(int count);

// Mitchell's best-candidate algorithm.
std::vector<Point2> best_candidate(int count, UnitDiskSampler& sampler);

// Yuksel 2015 weighted sample elimination from 5 * count candidates.
std::vector<Point2> sample_elimination(int count, UnitDiskSampler& sampler);

// The square [-1, 1]^2 in `count` cells of equal area, one jittered point in
// each: rows of floor(sqrt(count)) bands, each band as tall as its share of
// the cells (square_sets.cpp).
std::vector<Point2> square_stratified(int count, UnitDiskSampler& sampler);

// Roberts' R2 low-discrepancy sequence in [-1, 1]^2, shifted by a random
// offset from `sampler` (square_sets.cpp).
std::vector<Point2> square_r2(int count, UnitDiskSampler& sampler);

}  // namespace penumbra::disk_detail
