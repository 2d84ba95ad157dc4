#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "disk/generators.hpp"
#include "penumbra/compiler/disk.hpp"

namespace penumbra {
namespace {

constexpr std::string_view kBestCandidate = "best_candidate";
constexpr std::string_view kSampleElimination = "sample_elimination";

}  // namespace

std::string allowed_disk_methods() {
  return std::string(kBestCandidate) + ", " + std::string(kSampleElimination) + ", " +
         std::string(kSquareStratified) + ", " + std::string(kSquareR2);
}

Status check_sample_count(int count) {
  if (count >= 1 && count <= kMaxSamples) return {};
  return make_error(Error::Kind::bad_input, "",
                    "sample count " + std::to_string(count) + " is out of range; allowed 1.." +
                        std::to_string(kMaxSamples));
}

Status check_disk_method(std::string_view method) {
  if (method == kBestCandidate || method == kSampleElimination || method == kSquareStratified ||
      method == kSquareR2) {
    return {};
  }
  return make_error(Error::Kind::bad_input, "",
                    "unknown disk method '" + std::string(method) +
                        "'; allowed methods: " + allowed_disk_methods());
}

Result<Disk> generate_disk(const DiskOptions& options) {
  PENUMBRA_TRY(check_sample_count(options.count));
  PENUMBRA_TRY(check_disk_method(options.method));
  disk_detail::UnitDiskSampler sampler(options.seed);
  Disk disk;
  disk.name = options.method;
  disk.method = options.method;
  disk.seed = options.seed;
  if (options.method == kBestCandidate) {
    disk.points = disk_detail::best_candidate(options.count, sampler);
  } else if (options.method == kSquareStratified) {
    disk.points = disk_detail::square_stratified(options.count, sampler);
  } else if (options.method == kSquareR2) {
    disk.points = disk_detail::square_r2(options.count, sampler);
  } else {
    disk.points = disk_detail::sample_elimination(options.count, sampler);
  }
  disk.normalized_min_distance = normalized_min_distance(disk.points, sample_shape(options.method));
  return disk;
}

double normalized_min_distance(std::span<const Point2> points, SampleShape shape) {
  if (points.size() < 2) return 1.0;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      nearest = std::min(nearest, disk_detail::squared_distance(points[i], points[j]));
    }
  }
  const double bound = disk_detail::hexagonal_distance_bound(static_cast<int>(points.size()));
  // The bound scales with the square root of the area: 4 for the square, pi
  // for the disk.
  return std::sqrt(nearest) /
         (shape == SampleShape::square ? bound * std::sqrt(4.0 / std::numbers::pi) : bound);
}

namespace disk_detail {

double hexagonal_distance_bound(int count) {
  return std::sqrt(2.0 * std::numbers::pi / (std::sqrt(3.0) * count));
}

}  // namespace disk_detail
}  // namespace penumbra
