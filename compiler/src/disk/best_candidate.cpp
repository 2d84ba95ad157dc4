#include <algorithm>
#include <limits>

#include "disk/generators.hpp"

namespace penumbra::disk_detail {
namespace {

// Mitchell's k: candidates drawn per existing point.
constexpr int kCandidatesPerPoint = 10;

double nearest_squared_distance(const Point2& p, const std::vector<Point2>& points) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const Point2& q : points) nearest = std::min(nearest, squared_distance(p, q));
  return nearest;
}

}  // namespace

// The i-th point (1-based) is the farthest of k * i candidates from the points
// so far; the candidate count grows so that the fill stays even as it densifies.
std::vector<Point2> best_candidate(int count, UnitDiskSampler& sampler) {
  std::vector<Point2> points;
  points.reserve(static_cast<std::size_t>(count));
  for (int i = 1; i <= count; ++i) {
    Point2 best{};
    double best_distance = -1.0;
    for (int c = 0; c < kCandidatesPerPoint * i; ++c) {
      const Point2 candidate = sampler.next();
      const double distance = nearest_squared_distance(candidate, points);
      if (distance > best_distance) {
        best = candidate;
        best_distance = distance;
      }
    }
    points.push_back(best);
  }
  return points;
}

}  // namespace penumbra::disk_detail
