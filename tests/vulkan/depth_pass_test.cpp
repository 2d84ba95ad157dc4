// The depth pass: casters at known depths into both images of a shadow map.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "test_programs.hpp"

namespace penumbra {
namespace {

constexpr int kSize = 16;
const test::TestLight kLight;  // n = 9.5, Fw = 3.75, depth_scale = 1/32

// The scene: a near quad (z = 12) drawn first, overlapping a far quad
// (z = 24) drawn after it, so the far one must lose the depth test.
std::vector<std::array<float, 3>> scene() {
  std::vector<std::array<float, 3>> triangles;
  test::add_caster_quad(triangles, kLight, 0.5f, 1.25f, 0.5f, 0.875f, 12.0f);  // runs off the right
  test::add_caster_quad(triangles, kLight, 0.25f, 0.75f, 0.25f, 0.75f, 24.0f);
  return triangles;
}

// Linear z at texel (i, j)'s centre; 0 where nothing covers it.
float expected_z(int i, int j) {
  const float u = (static_cast<float>(i) + 0.5f) / kSize;
  const float v = (static_cast<float>(j) + 0.5f) / kSize;
  if (u > 0.5f && v > 0.5f && v < 0.875f) return 12.0f;
  if (u > 0.25f && u < 0.75f && v > 0.25f && v < 0.75f) return 24.0f;
  return 0.0f;
}

float expected_depth(int i, int j) {
  const float z = expected_z(i, j);
  return z > 0.0f ? z * kLight.depth_scale : 1.0f;  // cleared to the far plane
}

TEST(DepthPassTest, QuadsLandAtTheirNormalizedDepth) {
  auto engine = test::make_engine();
  ASSERT_NE(engine, nullptr);
  const auto triangles = scene();
  auto map = engine->render_depth(test::depth_program(), triangles, kSize, kSize,
                                  test::make_params(kLight, kSize, kSize, kSize, kSize));
  ASSERT_TRUE(map) << map.error().to_string();
  auto depth = engine->read_shadow_map(**map);
  ASSERT_TRUE(depth) << depth.error().to_string();
  int near = 0;
  int far = 0;
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      EXPECT_NEAR(depth->at(i, j), expected_depth(i, j), 1e-6) << "texel " << i << ", " << j;
      near += expected_z(i, j) == 12.0f;
      far += expected_z(i, j) == 24.0f;
    }
  }
  EXPECT_EQ(near, 8 * 6);
  EXPECT_EQ(far, 8 * 8 - 4 * 4);
}

// The depth image holds the same values: compare just in front of and just
// behind each texel's surface at its centre (where the bilinear weights
// select that texel alone).
TEST(DepthPassTest, DepthImageHoldsTheSameDepth) {
  auto engine = test::make_engine();
  ASSERT_NE(engine, nullptr);
  const ParamBlock params = test::make_params(kLight, kSize, kSize, kSize, kSize);
  const auto triangles = scene();
  auto map = engine->render_depth(test::depth_program(), triangles, kSize, kSize, params);
  ASSERT_TRUE(map) << map.error().to_string();

  FloatImage in_front(kSize, kSize, 3);
  FloatImage behind(kSize, kSize, 3);
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      const float u = (static_cast<float>(i) + 0.5f) / kSize;
      const float v = (static_cast<float>(j) + 0.5f) / kSize;
      const float z = expected_z(i, j);
      const float z_far = 1.0f / kLight.depth_scale;
      for (FloatImage* image : {&in_front, &behind}) {
        image->at(i, j, 0) = u;
        image->at(i, j, 1) = v;
      }
      in_front.at(i, j, 2) = (z > 0.0f ? z : z_far) - 0.01f;
      behind.at(i, j, 2) = z > 0.0f ? z + 0.01f : 0.0f;  // background: in front, lit
    }
  }
  auto lit = engine->run_query(test::compare_program(), **map, in_front, params);
  ASSERT_TRUE(lit) << lit.error().to_string();
  auto shadowed = engine->run_query(test::compare_program(), **map, behind, params);
  ASSERT_TRUE(shadowed) << shadowed.error().to_string();
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      EXPECT_EQ(lit->at(i, j), 1.0f) << "texel " << i << ", " << j;
      EXPECT_EQ(shadowed->at(i, j), expected_z(i, j) > 0.0f ? 0.0f : 1.0f)
          << "texel " << i << ", " << j;
    }
  }
}

// A D24 or D16 map's depth image holds the rasterizer's depth rounded to
// its format's codes: read back as the floats a sampler returns, each is
// the float nearest a whole number of steps, within one step of the D32
// map's.
TEST(DepthPassTest, UnormDepthImagesHoldTheirFormatsCodes) {
  auto engine = test::make_engine();
  ASSERT_NE(engine, nullptr);
  const ParamBlock params = test::make_params(kLight, kSize, kSize, kSize, kSize);
  const auto triangles = scene();
  auto exact = engine->render_depth(test::depth_program(), triangles, kSize, kSize, params);
  ASSERT_TRUE(exact) << exact.error().to_string();
  auto exact_depth = engine->read_shadow_depth(**exact);
  ASSERT_TRUE(exact_depth) << exact_depth.error().to_string();
  for (const DepthFormat format : {DepthFormat::d24_unorm, DepthFormat::d16_unorm}) {
    SCOPED_TRACE(std::string(to_string(format)));
    auto map = engine->render_depth(test::depth_program(), triangles, kSize, kSize, params, format);
    ASSERT_TRUE(map) << map.error().to_string();
    auto depth = engine->read_shadow_depth(**map);
    ASSERT_TRUE(depth) << depth.error().to_string();
    const double step = depth_step(format);
    int rounded = 0;
    for (std::size_t t = 0; t < depth->data.size(); ++t) {
      // D24's codes are not all floats: the nearest float to a whole step.
      const auto code = static_cast<std::uint32_t>(std::lround(depth->data[t] / step));
      EXPECT_EQ(depth->data[t], unorm_depth(format, code)) << "texel " << t;
      EXPECT_LE(std::abs(double(depth->data[t]) - exact_depth->data[t]), step) << "texel " << t;
      rounded += depth->data[t] != exact_depth->data[t];
    }
    // 12 / 32 and 24 / 32 are no whole number of D16 or D24 steps.
    EXPECT_GT(rounded, 0);
  }
}

TEST(DepthPassTest, NoTrianglesLeavesTheFarPlane) {
  auto engine = test::make_engine();
  ASSERT_NE(engine, nullptr);
  auto map =
      engine->render_depth(test::depth_program(), {}, 3, 2, test::make_params(kLight, 3, 2, 3, 2));
  ASSERT_TRUE(map) << map.error().to_string();
  auto depth = engine->read_shadow_map(**map);
  ASSERT_TRUE(depth) << depth.error().to_string();
  EXPECT_EQ(depth->data, std::vector<float>(6, 1.0f));
}

TEST(DepthPassTest, RejectsPartialTrianglesAndBadSizes) {
  auto engine = test::make_engine();
  ASSERT_NE(engine, nullptr);
  const ParamBlock params = test::make_params(kLight, 4, 4, 4, 4);
  const std::vector<std::array<float, 3>> two_vertices{{0, 0, 10}, {1, 0, 10}};
  auto partial = engine->render_depth(test::depth_program(), two_vertices, 4, 4, params);
  ASSERT_FALSE(partial);
  EXPECT_NE(partial.error().message.find("2 vertices are not a whole number of triangles"),
            std::string::npos);
  auto empty = engine->render_depth(test::depth_program(), {}, 0, 4, params);
  ASSERT_FALSE(empty);
  EXPECT_EQ(empty.error().where, "shadow map");
  EXPECT_NE(empty.error().message.find("size 0x4 is out of range"), std::string::npos);
}

}  // namespace
}  // namespace penumbra
