// Poisson disks: the whitepaper's 16-point set and the project's deterministic
// generators. See docs/disks.md.
#pragma once

#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>
#include <string_view>

#include "penumbra/model/model.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

struct DiskOptions {
  int count = 16;                             // number of points, 1..kMaxSamples
  std::uint64_t seed = 1;                     // std::mt19937_64 seed; same seed, same disk
  std::string method = "sample_elimination";  // "best_candidate" or "sample_elimination"
};

// Generates a disk: bit-identical on every platform for the same options.
// Points lie in the unit disk, are float32 values and come in generation order.
// The disk's name is its method's name (a manifest renames it to its family).
Result<Disk> generate_disk(const DiskOptions& options);

// The NVIDIA PCSS whitepaper's 16 points, point for point (name
// "whitepaper16", method "whitepaper", seed 0). Half of them lie outside the
// unit disk, up to radius 1.23.
Disk whitepaper16();

// Minimum pairwise distance divided by the hexagonal-packing bound for
// N points in the unit disk, sqrt(2 pi / (sqrt(3) N)); 1.0 for fewer than 2.
double normalized_min_distance(std::span<const Point2> points);

// {"name", "method", "seed", "count", "normalized_min_distance", "points"};
// points are [x, y] pairs that read back into float with the same bits.
nlohmann::json disk_to_json(const Disk& disk);
// The two halves of that object: the bare array of points, and everything
// else.
nlohmann::json disk_points_json(const Disk& disk);
nlohmann::json disk_info_json(const Disk& disk);
// The disk back from those halves (index.json's `disks` table passes a record
// and its `points`); a member missing from `info` stays at its default. Throws
// nlohmann::json::exception on a malformed point.
Disk disk_from_json(const nlohmann::json& points, const nlohmann::json& info);

// "best_candidate, sample_elimination", for messages and help text.
std::string allowed_disk_methods();

// Errors (kind bad_input, no location) that say what is allowed.
Status check_sample_count(int count);
Status check_disk_method(std::string_view method);

}  // namespace penumbra
