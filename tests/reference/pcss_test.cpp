// PCSS on hand-built maps: the early out, full occlusion, the filter radius
// formula, penumbra growth, bias and ambiguous blocker searches.
#include <gtest/gtest.h>

#include "fixtures.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {
namespace {

using testing::column_split_map;
using testing::pcss_variant;

const std::vector<Point2> kCross = {{0.0f, 0.0f}, {1.0f, 0.0f},  {-1.0f, 0.0f},
                                    {0.0f, 1.0f}, {0.0f, -1.0f}, {0.5f, 0.5f}};

Sample pcss_at(const FloatImage& map, const Query& q, const LightParams& light = {},
               const Variant& variant = pcss_variant(kCross, kCross)) {
  return evaluate(variant, ShadowMapView(map), light, q);
}

TEST(Pcss, NoBlockerIsFullyLit) {
  const FloatImage map(64, 64, 1, 20.0f);
  const Sample s = pcss_at(map, {0.5, 0.5, 15.0});
  EXPECT_EQ(s.visibility, 1.0);
  EXPECT_EQ(s.ambiguous, Ambiguity::none);
}

TEST(Pcss, FullyOccludedIsBlack) {
  const FloatImage map(64, 64, 1, 10.0f);
  EXPECT_EQ(pcss_at(map, {0.5, 0.5, 15.0}).visibility, 0.0);
  EXPECT_EQ(pcss_at(map, {0.01, 0.99, 15.0}).visibility, 0.0);  // clamped at the corner
}

TEST(Pcss, FilterRadiusFollowsTheWhitepaper) {
  // One blocker point at the receiver, one PCF point (1, 0): the PCF sample
  // lands at u + r, r = (z_r - z_b) / z_b * L_uv * n / z_r.
  const FloatImage map = column_split_map(256, 256, 128, 10.0f, 32.0f);
  const double z_r = 16.0;
  const double r = (z_r - 10.0) / 10.0 * (0.5 / 3.75) * 9.5 / z_r;
  const double u = 127.75 / 256 - r;  // u + r is at x = (u + r) W - 0.5 = 127.25
  const Variant variant = pcss_variant({{0.0f, 0.0f}}, {{1.0f, 0.0f}});
  EXPECT_NEAR(pcss_at(map, {u, 0.5, z_r}, {}, variant).visibility, 0.25, 1e-9);
  // The bias moves comparisons only, not the geometry.
  LightParams biased;
  biased.bias = 0.01;
  EXPECT_NEAR(pcss_at(map, {u, 0.5, z_r}, biased, variant).visibility, 0.25, 1e-9);
}

TEST(Pcss, PenumbraGrowsWithTheBlockerDistance) {
  // A receiver just on the lit side of an edge gets darker as the blocker
  // moves from the receiver towards the light.
  const double z_r = 16.0;
  double previous = 1.0;
  for (float z_b = 15.5f; z_b >= 10.0f; z_b -= 0.5f) {
    const FloatImage map = column_split_map(256, 256, 128, z_b, 32.0f);
    const double visibility = pcss_at(map, {0.52, 0.5, z_r}).visibility;
    EXPECT_LE(visibility, previous) << "z_b = " << z_b;
    previous = visibility;
  }
  EXPECT_LT(previous, 0.9);  // the widest penumbra reaches well past u = 0.52
}

TEST(Pcss, SearchWidthBoundsTheBlockerSearch) {
  // The search width is L_uv (z_r - n) / z_r = 0.05 uv at z_r = 15.2; the
  // occluder edge at u = 0.5 is found from u = 0.54 but not from u = 0.56.
  const FloatImage map = column_split_map(1024, 4, 512, 10.0f, 32.0f);
  EXPECT_LT(pcss_at(map, {0.54, 0.5, 15.2}).visibility, 1.0);
  EXPECT_EQ(pcss_at(map, {0.56, 0.5, 15.2}).visibility, 1.0);
}

TEST(Pcss, SearchWidthUsesTheUnbiasedReceiverDepth) {
  // z_r = 15.2, bias 0.2: the search width is L_uv (15.2 - n) / 15.2 = 0.05,
  // so from u = 0.6 the point (-1, 0) reads u = 0.55, texel 563, at depth 10
  // (with z_r - bias it would read texel 564, at depth 12). The point (0, 0)
  // reads depth 12, the average 11 sets the radius, and the PCF point (1, 0)
  // lands on the edge of the lit columns from 647 on.
  FloatImage map = column_split_map(1024, 4, 564, 10.0f, 12.0f);
  for (int j = 0; j < 4; ++j) {
    for (int i = 647; i < 1024; ++i) map.at(i, j) = 32.0f;
  }
  LightParams light;
  light.bias = 0.2;
  const double r = (15.2 - 11.0) / 11.0 * (0.5 / 3.75) * 9.5 / 15.2;
  const double expected = (0.6 + r) * 1024 - 0.5 - 646;  // the lit texel's bilinear weight
  ASSERT_GT(expected, 0.1);
  ASSERT_LT(expected, 0.9);
  const Variant variant = pcss_variant({{0.0f, 0.0f}, {-1.0f, 0.0f}}, {{1.0f, 0.0f}});
  EXPECT_NEAR(pcss_at(map, {0.6, 0.5, 15.2}, light, variant).visibility, expected, 1e-9);
}

TEST(Pcss, BiasAppliesToTheBlockerTest) {
  const FloatImage map(64, 64, 1, 10.0f);
  LightParams light;
  EXPECT_EQ(pcss_at(map, {0.5, 0.5, 10.05}, light).visibility, 0.0);
  light.bias = 0.1;
  EXPECT_EQ(pcss_at(map, {0.5, 0.5, 10.05}, light).visibility, 1.0);
}

TEST(Pcss, AmbiguousWhenABlockerSampleSitsOnADifferingBoundary) {
  const Variant single = pcss_variant({{0.0f, 0.0f}}, {{0.0f, 0.0f}});
  const Query on_boundary{0.5, 0.5 + 0.5 / 64, 15.0};  // u W = 32 exactly
  // Blocker against non-blocker.
  EXPECT_EQ(pcss_at(column_split_map(64, 64, 32, 10.0f, 20.0f), on_boundary, {}, single).ambiguous,
            Ambiguity::texel_boundary);
  // Two blockers at different depths change the average.
  EXPECT_EQ(pcss_at(column_split_map(64, 64, 32, 10.0f, 12.0f), on_boundary, {}, single).ambiguous,
            Ambiguity::texel_boundary);
  // Two non-blockers at different depths do not matter.
  EXPECT_EQ(pcss_at(column_split_map(64, 64, 32, 16.0f, 20.0f), on_boundary, {}, single).ambiguous,
            Ambiguity::none);
  // Away from the boundary nothing is ambiguous.
  const Query inside{0.5 + 0.3 / 64, 0.5 + 0.5 / 64, 15.0};
  EXPECT_EQ(pcss_at(column_split_map(64, 64, 32, 10.0f, 20.0f), inside, {}, single).ambiguous,
            Ambiguity::none);
}

}  // namespace
}  // namespace penumbra::reference
