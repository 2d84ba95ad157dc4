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
  return std::string(kBestCandidate) + ", " + std::string(kSampleElimination);
}

Status check_sample_count(int count) {
  if (count >= 1 && count <= kMaxSamples) return {};
  return make_error(Error::Kind::bad_input, "",
                    "sample count " + std::to_string(count) + " is out of range; allowed 1.." +
                        std::to_string(kMaxSamples));
}

Status check_disk_method(std::string_view method) {
  if (method == kBestCandidate || method == kSampleElimination) return {};
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
  disk.points = options.method == kBestCandidate
                    ? disk_detail::best_candidate(options.count, sampler)
                    : disk_detail::sample_elimination(options.count, sampler);
  disk.normalized_min_distance = normalized_min_distance(disk.points);
  return disk;
}

double normalized_min_distance(std::span<const Point2> points) {
  if (points.size() < 2) return 1.0;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      nearest = std::min(nearest, disk_detail::squared_distance(points[i], points[j]));
    }
  }
  return std::sqrt(nearest) /
         disk_detail::hexagonal_distance_bound(static_cast<int>(points.size()));
}

namespace disk_detail {

double hexagonal_distance_bound(int count) {
  return std::sqrt(2.0 * std::numbers::pi / (std::sqrt(3.0) * count));
}

}  // namespace disk_detail
}  // namespace penumbra
