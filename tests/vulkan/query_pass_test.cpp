// The query pass: bilinear comparisons through shadow_cmp, and point reads
// through shadow_depth in a program without shadow_cmp (Direct3D 9 style).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "test_programs.hpp"

namespace penumbra {
namespace {

// 4 x 4 map, row j = 0 first: an occluder (0.2) in the top-left 2 x 2 corner.
FloatImage corner_map() {
  FloatImage map(4, 4, 1, 0.8f);
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i) map.at(i, j) = 0.2f;
  }
  return map;
}

// Unscaled depth and no bias, so z_r is the comparison reference itself.
test::TestLight unscaled() {
  test::TestLight light;
  light.depth_scale = 1.0f;
  return light;
}

// docs/shader-interface.md's bilinear comparison: the four texels around
// (u W - 0.5, v H - 0.5), clamped to the edge, lit when ref <= depth.
float bilinear_comparison(const FloatImage& map, float u, float v, float ref) {
  const float x = u * static_cast<float>(map.width) - 0.5f;
  const float y = v * static_cast<float>(map.height) - 0.5f;
  const float x0 = std::floor(x);
  const float y0 = std::floor(y);
  auto lit = [&](float i, float j) {
    const int ci = std::clamp(static_cast<int>(i), 0, map.width - 1);
    const int cj = std::clamp(static_cast<int>(j), 0, map.height - 1);
    return ref <= map.at(ci, cj) ? 1.0f : 0.0f;
  };
  const float wx = x - x0;
  const float wy = y - y0;
  return (1 - wy) * ((1 - wx) * lit(x0, y0) + wx * lit(x0 + 1, y0)) +
         wy * ((1 - wx) * lit(x0, y0 + 1) + wx * lit(x0 + 1, y0 + 1));
}

Result<FloatImage> query(Engine& engine, const PassProgram& program, const FloatImage& map,
                         const FloatImage& receivers) {
  auto shadow_map = engine.upload_shadow_map(map);
  if (!shadow_map) return shadow_map.error();
  return engine.run_query(
      program, **shadow_map, receivers,
      test::make_params(unscaled(), map.width, map.height, receivers.width, receivers.height));
}

TEST(QueryPassTest, BilinearComparisonAtHandPickedPoints) {
  auto engine = test::make_engine();
  ASSERT_NE(engine, nullptr);
  struct Case {
    std::array<float, 3> point;  // u, v, z_r
    float visibility;
  };
  const std::vector<Case> cases = {
      // Texel (0, 0)'s centre: that texel alone, an occluder.
      {{0.125f, 0.125f, 0.5f}, 0.0f},
      // Between columns 1 and 2 of row 0 (x = 1.25): 0.75 * occluded + 0.25 * lit.
      {{0.4375f, 0.125f, 0.5f}, 0.25f},
      // Between rows 1 and 2 of column 0 (y = 1.25): likewise, vertically.
      {{0.125f, 0.4375f, 0.5f}, 0.25f},
      // The corner of the occluder (x = y = 1.5): one occluded texel of four.
      {{0.5f, 0.5f, 0.5f}, 0.75f},
      // Beyond the map's corner: clamp-to-edge repeats texel (0, 0).
      {{0.0f, 0.0f, 0.5f}, 0.0f},
      // A reference equal to the stored depth is lit (LESS_OR_EQUAL).
      {{0.875f, 0.875f, 0.8f}, 1.0f},
      // In front of everything.
      {{0.5f, 0.5f, 0.1f}, 1.0f},
  };
  std::vector<std::array<float, 3>> points;
  for (const Case& c : cases) points.push_back(c.point);
  const FloatImage map = corner_map();
  auto visibility = query(*engine, test::compare_program(), map, test::receivers_row(points));
  ASSERT_TRUE(visibility) << visibility.error().to_string();
  ASSERT_EQ(visibility->width, static_cast<int>(cases.size()));
  ASSERT_EQ(visibility->channels, 1);
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const auto& [u, v, z] = cases[k].point;
    EXPECT_NEAR(bilinear_comparison(map, u, v, z), cases[k].visibility, 1e-6) << "case " << k;
    EXPECT_NEAR(visibility->at(static_cast<int>(k), 0), cases[k].visibility, 2.0 / 256)
        << "case " << k << " at (" << u << ", " << v << ", " << z << ")";
  }
}

// Weights that are not multiples of 1/256: the device's 8 sub-texel bits
// round them, by at most 2/256 here.
TEST(QueryPassTest, BilinearComparisonSweepWithinSubTexelPrecision) {
  auto engine = test::make_engine();
  ASSERT_NE(engine, nullptr);
  const FloatImage map = corner_map();
  std::vector<std::array<float, 3>> points;
  for (int k = 0; k < 64; ++k) {
    const float t = static_cast<float>(k) / 63.0f;
    points.push_back({0.1f + 0.7f * t, 0.3f + 0.31f * t, 0.5f});  // crosses both edges
    points.push_back({0.37f, 0.05f + 0.9f * t, 0.5f});
  }
  auto visibility = query(*engine, test::compare_program(), map, test::receivers_row(points));
  ASSERT_TRUE(visibility) << visibility.error().to_string();
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto& [u, v, z] = points[k];
    EXPECT_NEAR(visibility->at(static_cast<int>(k), 0), bilinear_comparison(map, u, v, z),
                2.0 / 256)
        << "point " << k << " (" << u << ", " << v << ")";
  }
}

// Without shadow_cmp, shadow_depth binds the R32F colour image; with it, the
// depth image. Both hold the map's values, read back exactly.
TEST(QueryPassTest, ShadowDepthReadsTheMapWithAndWithoutShadowCmp) {
  auto engine = test::make_engine();
  ASSERT_NE(engine, nullptr);
  FloatImage map(4, 4, 1);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) map.at(i, j) = static_cast<float>(1 + i + 4 * j) / 17.0f;
  }
  std::vector<std::array<float, 3>> centres;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      centres.push_back(
          {(static_cast<float>(i) + 0.5f) / 4, (static_cast<float>(j) + 0.5f) / 4, 0});
    }
  }
  for (const PassProgram& program : {test::point_program(), test::point_with_cmp_program()}) {
    auto read = query(*engine, program, map, test::receivers_row(centres));
    ASSERT_TRUE(read) << read.error().to_string();
    EXPECT_EQ(read->data, map.data);
  }
}

TEST(QueryPassTest, ReceiversNeedThreeOrFourChannels) {
  auto engine = test::make_engine();
  ASSERT_NE(engine, nullptr);
  auto result = query(*engine, test::compare_program(), corner_map(), FloatImage(2, 2, 1));
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().where, "receivers");
  EXPECT_NE(result.error().message.find("expected 3 or 4 channels"), std::string::npos);
}

}  // namespace
}  // namespace penumbra
