#include <algorithm>
#include <cmath>
#include <queue>
#include <utility>

#include "disk/generators.hpp"

namespace penumbra::disk_detail {
namespace {

// Yuksel's defaults: 5 candidates per kept point; weight limiting with
// beta = 0.65, gamma = 1.5.
constexpr int kCandidatesPerPoint = 5;
constexpr double kLimitBeta = 0.65;

struct Neighbor {
  std::size_t index;
  double weight;
};

// (1 - d / d_max)^8 by repeated squaring: std::pow is not bit-identical
// across C libraries, multiplication is.
double weight(double distance, double d_max) {
  const double x = 1.0 - distance / d_max;
  const double x2 = x * x;
  const double x4 = x2 * x2;
  return x4 * x4;
}

// Weight limiting: distances below d_min weigh as d_min, so a tight pair does
// not dominate its neighbourhood. d_min = d_max (1 - (N/M)^gamma) beta, with
// x^1.5 written as x sqrt(x) (sqrt is exactly rounded everywhere, pow is not).
double limited_distance(double d_max) {
  const double ratio = 1.0 / kCandidatesPerPoint;
  return d_max * (1.0 - ratio * std::sqrt(ratio)) * kLimitBeta;
}

}  // namespace

// Every candidate's weight sums its closeness to the neighbours within
// d_max = 2 r_max. The heaviest (most crowded) candidate is removed and its
// neighbours' weights drop, until `count` remain. The heap is lazy: an entry
// whose weight no longer matches is stale and skipped. Ties go to the higher
// index, deterministically.
std::vector<Point2> sample_elimination(int count, UnitDiskSampler& sampler) {
  const std::size_t m = static_cast<std::size_t>(kCandidatesPerPoint * count);
  std::vector<Point2> candidates(m);
  for (Point2& p : candidates) p = sampler.next();

  // Brute-force neighbour search: m <= 5 * kMaxSamples, so O(m^2) is cheap.
  const double d_max = hexagonal_distance_bound(count);
  const double d_min = limited_distance(d_max);
  std::vector<std::vector<Neighbor>> neighbors(m);
  std::vector<double> weights(m, 0.0);
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = i + 1; j < m; ++j) {
      const double distance = std::sqrt(squared_distance(candidates[i], candidates[j]));
      if (distance >= d_max) continue;
      const double w = weight(std::max(distance, d_min), d_max);
      neighbors[i].push_back({j, w});
      neighbors[j].push_back({i, w});
      weights[i] += w;
      weights[j] += w;
    }
  }

  std::priority_queue<std::pair<double, std::size_t>> heap;
  for (std::size_t i = 0; i < m; ++i) heap.emplace(weights[i], i);
  std::vector<bool> removed(m, false);
  for (std::size_t remaining = m; remaining > static_cast<std::size_t>(count);) {
    const auto [w, i] = heap.top();
    heap.pop();
    if (removed[i] || w != weights[i]) continue;
    removed[i] = true;
    --remaining;
    for (const Neighbor& n : neighbors[i]) {
      if (removed[n.index]) continue;
      weights[n.index] -= n.weight;
      heap.emplace(weights[n.index], n.index);
    }
  }

  std::vector<Point2> points;
  for (std::size_t i = 0; i < m; ++i) {
    if (!removed[i]) points.push_back(candidates[i]);
  }
  return points;
}

}  // namespace penumbra::disk_detail
