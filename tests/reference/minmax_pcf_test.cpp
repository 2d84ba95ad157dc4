// minmax_pcf: the hierarchical count of the min-max traversal equals the
// brute-force count exactly, for kernels from 1 to 128 and windows anywhere,
// across every edge and corner of non-power-of-two maps; the reference's
// window and result in float; its variant checks.
#include "penumbra/reference/minmax_pcf.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "fixtures.hpp"
#include "penumbra/reference/sampling.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {
namespace {

struct NamedMap {
  std::string name;
  FloatImage depth;
  std::vector<float> references;  // receiver depths to count against
};

std::vector<NamedMap> maps() {
  std::vector<NamedMap> result;
  result.push_back(
      {"random", testing::random_map(250, 190, 10.0f, 20.0f, 3), {9.0f, 15.0f, 21.0f}});
  result.push_back(
      {"blocky", testing::blocky_map(250, 190, 40, 10.0f, 20.0f, 32.0f, 5), {12.5f, 17.0f, 33.0f}});
  for (const Scene& scene : builtin_scenes()) {
    std::vector<float> references = {float(scene.plane_z0), float(scene.far_z) + 1.0f};
    for (const Rect& r : scene.occluders) references.push_back(float(r.z) + 0.25f);
    result.push_back({scene.name,
                      ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z),
                      references});
  }
  return result;
}

// Texel columns (or rows) whose K-window crosses every edge, lies wholly
// outside, inside or across the middle of a map `size` texels wide.
std::vector<int> window_centres(int size, int kernel, std::mt19937& generator) {
  const int half = kernel / 2;
  std::vector<int> centres = {-half - 2,
                              -half - 1,
                              -half,
                              -1,
                              0,
                              1,
                              half - 1,
                              half,
                              kernel,
                              size / 2,
                              size - half - 1,
                              size - half,
                              size - 2,
                              size - 1,
                              size,
                              size + half - 1,
                              size + half,
                              size + kernel};
  std::uniform_int_distribution<int> anywhere(-half, size + half);
  for (int k = 0; k < 6; ++k) centres.push_back(anywhere(generator));
  return centres;
}

class MinMaxTraversal : public ::testing::TestWithParam<int> {};

TEST_P(MinMaxTraversal, CountEqualsBruteForceEverywhere) {
  const int kernel = GetParam();
  std::mt19937 generator{unsigned(kernel)};
  int checked = 0, partial = 0;
  for (const NamedMap& named : maps()) {
    const ShadowMapView map(named.depth);
    const MinMaxMip mip(map);
    const std::vector<int> columns = window_centres(map.width(), kernel, generator);
    const std::vector<int> rows = window_centres(map.height(), kernel, generator);
    for (int cy : rows) {
      for (int cx : columns) {
        // A receiver a quarter texel into texel (cx, cy).
        const double u = (cx + 0.25) / map.width(), v = (cy + 0.25) / map.height();
        const TexelRect window = minmax_pcf_window(map, u, v, kernel);
        ASSERT_EQ(window.x0, cx - kernel / 2);
        ASSERT_EQ(window.y1, cy - kernel / 2 + kernel - 1);
        for (float z_ref : named.references) {
          const long long expected = count_occluders_brute_force(map, window, z_ref);
          const MipCount counted = count_occluders(mip, window, z_ref);
          ASSERT_EQ(counted.count, expected) << named.name << ": K " << kernel << " at texel " << cx
                                             << ", " << cy << ", z " << z_ref;
          ASSERT_LE(counted.visits, minmax_max_visits(kernel))
              << named.name << " at " << cx << ", " << cy;
          ASSERT_LE(counted.reads, counted.visits);
          ++checked;
          const long long inside = clip(window, map.width(), map.height()).count();
          partial += expected > 0 && expected < inside;
        }
      }
    }
  }
  EXPECT_GT(checked, 10000);
  // Windows that mix occluding and lit texels make the traversal descend.
  if (kernel > 1) {
    EXPECT_GT(partial, checked / 100) << "too few windows mix the two";
  }
}

INSTANTIATE_TEST_SUITE_P(Kernels, MinMaxTraversal,
                         ::testing::Values(1, 2, 7, 8, 12, 45, 64, 127, 128),
                         [](const auto& param_info) {
                           return "K" + std::to_string(param_info.param);
                         });

TEST(MinMaxTraversal, ReadsFarFewerNodesThanTexelsOnFlatRegions) {
  // Over a flat occluder the 64 x 64 window is answered by its <= 2 x 2 roots
  // and the few nodes along their edges, not 4096 texel reads.
  const FloatImage depth(256, 256, 1, 10.0f);
  const MinMaxMip mip{ShadowMapView(depth)};
  const MipCount counted = count_occluders(mip, {100, 100, 163, 163}, 15.0f);
  EXPECT_EQ(counted.count, 64 * 64);
  EXPECT_LE(counted.reads, 4 * 8 + 4);
}

TEST(MinMaxTraversal, ReadCountsOnTheScenes) {
  // What the shader's .y reports for minmax_pcf on the built-in scenes, on
  // every other receiver row and column (docs/verification.md quotes this
  // table): the traversal reads a small fraction of the K^2 texels a
  // brute-force loop reads.
  std::printf("%-16s %5s %10s %10s %10s\n", "scene", "K", "K^2", "mean reads", "max reads");
  for (const Scene& scene : builtin_scenes()) {
    const FloatImage depth = ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z);
    const FloatImage points = receivers(scene, scene.receivers_width, scene.receivers_height);
    const ShadowMapView map(depth);
    const MinMaxMip mip(map);
    for (int kernel : {8, 16, 32, 64, 128}) {
      long long sum = 0;
      int most = 0, receivers_read = 0;
      for (int j = 0; j < points.height; j += 2) {
        for (int i = 0; i < points.width; i += 2) {
          const TexelRect window =
              minmax_pcf_window(map, points.at(i, j, 0), points.at(i, j, 1), kernel);
          const float z_ref = float_reference(points.at(i, j, 2), scene.light.bias);
          const int reads = count_occluders(mip, window, z_ref).reads;
          sum += reads;
          most = std::max(most, reads);
          ++receivers_read;
        }
      }
      const double mean = double(sum) / receivers_read;
      std::printf("%-16s %5d %10d %10.1f %10d\n", scene.name.c_str(), kernel, kernel * kernel, mean,
                  most);
      if (kernel >= 32) {
        EXPECT_LT(mean, kernel * kernel / 8.0) << scene.name << ", K " << kernel;
      }
    }
  }
}

// 8x8, columns 0-3 at depth 5 occlude a receiver at z = 10, columns 4-7 do not.
const FloatImage& half_occluded() {
  static const FloatImage map = testing::column_split_map(8, 8, 4, 5.0f, 20.0f);
  return map;
}

double visibility(int kernel, double u, double v, const LightParams& light = {}) {
  return evaluate(testing::minmax_pcf_variant(kernel), ShadowMapView(half_occluded()), light,
                  {u, v, 10.0})
      .visibility;
}

TEST(MinMaxPcf, CountsTheWindowAroundTheReceiversTexel) {
  // u W = 4.9: texel 4, K = 4 starts 2 to the left: columns 2..5, half occluded.
  EXPECT_EQ(visibility(4, 4.9 / 8, 0.5), 0.5);
  // K = 3 from texel 4: columns 3..5, one of three occludes: (9 - 3) / 9 as
  // the shader forms it, 6 times the float nearest 1/9.
  EXPECT_EQ(visibility(3, 4.9 / 8, 0.5), double(6.0f * (1.0f / 9.0f)));
  // K = 1 is the receiver's own texel.
  EXPECT_EQ(visibility(1, 3.9 / 8, 0.5), 0.0);
  EXPECT_EQ(visibility(1, 4.1 / 8, 0.5), 1.0);
}

TEST(MinMaxPcf, TexelsOutsideTheMapDoNotOcclude) {
  // K = 3 at texel (0, 0): columns and rows -1..1, of which 2 x 2 lie in the
  // map and occlude; the clamp-to-edge texels are not counted.
  EXPECT_EQ(visibility(3, 0.5 / 8, 0.5 / 8), double(5.0f * (1.0f / 9.0f)));
  // Wholly outside the map: nothing occludes.
  EXPECT_EQ(visibility(5, -2.0, 0.5), 1.0);
}

TEST(MinMaxPcf, VisibilityIsExactAtTheEndsAndCloseBetween) {
  double worst_ulps = 0.0;
  for (int kernel = 1; kernel <= 128; ++kernel) {
    const long long area = static_cast<long long>(kernel) * kernel;
    // K^2 times the float nearest 1 / K^2 is 0.99999994f for K = 11, 22, ...
    EXPECT_EQ(minmax_pcf_visibility(0, kernel), 1.0f) << "K " << kernel;
    EXPECT_EQ(minmax_pcf_visibility(area, kernel), 0.0f) << "K " << kernel;
    for (long long count = 1; count < area; ++count) {
      const double exact = 1.0 - double(count) / double(area);
      int exponent = 0;
      std::frexp(exact, &exponent);
      const double ulp = std::ldexp(1.0, exponent - 24);  // float spacing at `exact`
      const double ulps = std::abs(double(minmax_pcf_visibility(count, kernel)) - exact) / ulp;
      // The rounded 1 / K^2 is off by at most half its ulp (under one ulp of
      // the result) and the product adds half an ulp.
      ASSERT_LT(ulps, 1.5) << "K " << kernel << ", C " << count;
      worst_ulps = std::max(worst_ulps, ulps);
    }
  }
  // Not always within one ulp: K = 11, C = 25 is 1.06 ulp off.
  EXPECT_GT(worst_ulps, 1.0);
}

TEST(MinMaxPcf, ComparesInFloatLikeTheGpu) {
  // float(10) - float(0.1) is 9.89999962f, which equals float(9.9): the texel
  // does not occlude on the GPU, though 9.9f < 10 - 0.1 in double.
  const FloatImage depth(4, 4, 1, 9.9f);
  LightParams light;
  light.bias = 0.1;
  ASSERT_LT(double(9.9f), 10.0 - 0.1);
  EXPECT_EQ(float_reference(10.0, 0.1), 9.9f);
  const Sample s =
      evaluate(testing::minmax_pcf_variant(3), ShadowMapView(depth), light, {0.5, 0.5, 10.0});
  EXPECT_EQ(s.visibility, 1.0);
  EXPECT_EQ(s.ambiguous, Ambiguity::none);
}

TEST(MinMaxPcf, WindowUsesTheFloatProductOfUAndWidth) {
  // u = 0.02f is 0.0199999996: u * 250 is 4.9999999 in double but rounds to
  // exactly 5 in float, so the GPU's K = 1 window is texel 5, lit here.
  const FloatImage depth = testing::column_split_map(250, 2, 5, 5.0f, 20.0f);
  const double u = double(0.02f);
  ASSERT_LT(u * 250, 5.0);
  EXPECT_EQ(minmax_pcf_window(ShadowMapView(depth), u, 0.5, 1).x0, 5);
  EXPECT_EQ(
      evaluate(testing::minmax_pcf_variant(1), ShadowMapView(depth), {}, {u, 0.5, 10.0}).visibility,
      1.0);
}

TEST(CheckVariant, MinMaxPcfKernelAndTraversal) {
  EXPECT_TRUE(check_variant(testing::minmax_pcf_variant(1)));
  EXPECT_TRUE(check_variant(testing::minmax_pcf_variant(128)));
  EXPECT_FALSE(check_variant(testing::minmax_pcf_variant(0)));
  EXPECT_FALSE(check_variant(testing::minmax_pcf_variant(129)));
  Variant variant = testing::minmax_pcf_variant(16);
  variant.keys.traversal = "brute_force";
  EXPECT_TRUE(check_variant(variant));
  variant.keys.traversal = "quadtree";
  const auto bad = check_variant(variant);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("brute_force"), std::string::npos);
  variant.keys.kernel.reset();
  variant.keys.traversal.reset();
  EXPECT_FALSE(check_variant(variant));
}

}  // namespace
}  // namespace penumbra::reference
