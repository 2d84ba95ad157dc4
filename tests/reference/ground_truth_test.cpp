// The claim of docs/verification.md: against the exact visibility of the built-in scenes,
// backprojection is more accurate than PCSS. Every technique runs on the
// scene's ray-cast map and receivers. Receivers whose exact visibility depends
// on occluder parts outside the map's frustum are left out: no shadow-map
// technique can know those. The table printed here is the one in
// docs/verification.md ("Exact ground truth").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "fixtures.hpp"
#include "penumbra/compiler/disk.hpp"
#include "penumbra/reference/exact_visibility.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {
namespace {

// Sums of |technique - truth| over the receivers that count.
struct Errors {
  double sum = 0.0;
  double max = 0.0;
  std::size_t pixels = 0;

  double mean() const { return sum / double(pixels); }
  void add(const Errors& other) {
    sum += other.sum;
    max = std::max(max, other.max);
    pixels += other.pixels;
  }
};

Errors errors(const FloatImage& image, const FloatImage& truth, const std::vector<bool>& counts) {
  Errors e;
  for (std::size_t k = 0; k < truth.data.size(); ++k) {
    if (!counts[k]) continue;
    const double error = std::abs(double(image.data[k]) - double(truth.data[k]));
    e.sum += error;
    e.max = std::max(e.max, error);
    ++e.pixels;
  }
  return e;
}

std::vector<Variant> variants() {
  const Disk whitepaper = whitepaper16();
  const Disk poisson32 = generate_disk({32, 1, "sample_elimination"}).value();
  Variant pcss16 = testing::pcss_variant(whitepaper.points, whitepaper.points);
  pcss16.name = "pcss_b16_p16_whitepaper16";
  Variant pcss32 = testing::pcss_variant(poisson32.points, poisson32.points);
  pcss32.name = "pcss_b32_p32_poisson";
  Variant minmax16 = testing::pcss_minmax_variant(whitepaper.points);
  minmax16.name = "pcss_minmax_p16_whitepaper16";
  Variant minmax32 = testing::pcss_minmax_variant(poisson32.points);
  minmax32.name = "pcss_minmax_p32_poisson";
  return {pcss16, pcss32, minmax16, minmax32, testing::backprojection_variant()};
}

constexpr const char* kPcss[] = {"pcss_b16_p16_whitepaper16", "pcss_b32_p32_poisson"};

TEST(GroundTruth, BackprojectionIsCloserThanPcss) {
  std::map<std::string, Errors> all_scenes;
  std::printf("%-16s %-30s %9s %9s\n", "scene", "technique", "mean", "max");
  for (const Scene& scene : builtin_scenes()) {
    const FloatImage depth = ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z);
    const FloatImage points = receivers(scene, scene.receivers_width, scene.receivers_height);
    const FloatImage truth = exact_visibility_image(scene, points);
    const FloatImage seen = exact_visibility_image(clipped_to_map(scene), points);
    std::vector<bool> counts(truth.data.size());
    for (std::size_t k = 0; k < counts.size(); ++k) {
      counts[k] = std::abs(truth.data[k] - seen.data[k]) < 1e-6f;
    }
    const auto counted = std::count(counts.begin(), counts.end(), true);
    EXPECT_GT(double(counted), 0.95 * double(counts.size())) << scene.name;
    std::printf("%s: %ld of %zu receivers see no occluder outside the map\n", scene.name.c_str(),
                long(counted), counts.size());

    std::map<std::string, Errors> by_name;
    for (const Variant& variant : variants()) {
      const auto result = evaluate_image(variant, depth, scene.light, points);
      ASSERT_TRUE(result.ok()) << result.error().to_string();
      const Errors e = errors(result->visibility, truth, counts);
      by_name[variant.name] = e;
      all_scenes[variant.name].add(e);
      std::printf("%-16s %-30s %9.5f %9.5f\n", scene.name.c_str(), variant.name.c_str(), e.mean(),
                  e.max);
    }
    // Scene by scene backprojection is clearly better on average, least so
    // on tilted_overlap: there occluders overlap in the map, and the patches
    // of the near and the far one leave a gap between their projections
    // (measured ratios 0.26 to 0.69).
    for (const char* pcss : kPcss) {
      EXPECT_LT(by_name["backprojection"].mean(), 0.8 * by_name[pcss].mean())
          << scene.name << " against " << pcss;
    }
  }
  for (const auto& [name, e] : all_scenes) {
    std::printf("%-16s %-30s %9.5f %9.5f\n", "all three", name.c_str(), e.mean(), e.max);
  }
  // Over the three scenes (measured: 0.36 and 0.50 of PCSS's mean error).
  EXPECT_LT(all_scenes["backprojection"].mean(), 0.4 * all_scenes[kPcss[0]].mean());
  EXPECT_LT(all_scenes["backprojection"].mean(), 0.55 * all_scenes[kPcss[1]].mean());
  // pcss_minmax's 9-node blocker search stays near pcss's with the same
  // filter (measured 1.10 and 1.14 times its mean error; the smallest
  // minimum of 2x2 nodes was 1.97 and 1.92 times).
  EXPECT_LT(all_scenes["pcss_minmax_p16_whitepaper16"].mean(), 1.2 * all_scenes[kPcss[0]].mean());
  EXPECT_LT(all_scenes["pcss_minmax_p32_poisson"].mean(), 1.2 * all_scenes[kPcss[1]].mean());
}

}  // namespace
}  // namespace penumbra::reference
