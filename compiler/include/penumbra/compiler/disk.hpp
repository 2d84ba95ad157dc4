// Sample sets: the whitepaper's 16-point Poisson disk, the project's
// deterministic disk generators, and square sets that match a square
// light's shape. See docs/disks.md.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "penumbra/model/model.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

struct DiskOptions {
  int count = 16;          // number of points, 1..kMaxSamples
  std::uint64_t seed = 1;  // std::mt19937_64 seed; same seed, same set
  // "best_candidate" or "sample_elimination" (disks), "square_stratified" or
  // "square_r2" (squares)
  std::string method = "sample_elimination";
};

// Generates a set: bit-identical on every platform for the same options.
// Points lie in the method's shape, are float32 values and come in
// generation order. The set's name is its method's name (a manifest renames
// it to its family).
Result<Disk> generate_disk(const DiskOptions& options);

// The NVIDIA PCSS whitepaper's 16 points, point for point (name
// "whitepaper16", method "whitepaper", seed 0). Half of them lie outside the
// unit disk, up to radius 1.23.
Disk whitepaper16();

// Minimum pairwise distance divided by the hexagonal-packing bound for
// N points in the shape's area A, sqrt(2 A / (sqrt(3) N)) (A = pi for the
// unit disk, 4 for the square); 1.0 for fewer than 2.
double normalized_min_distance(std::span<const Point2> points,
                               SampleShape shape = SampleShape::disk);

// "best_candidate, sample_elimination, square_stratified, square_r2", for
// messages and help text.
std::string allowed_disk_methods();

// Errors (kind bad_input, no location) that say what is allowed.
Status check_sample_count(int count);
Status check_disk_method(std::string_view method);

}  // namespace penumbra
