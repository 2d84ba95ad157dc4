// pcss_minmax: the blocker depth is the mean of the blocking minima of the
// <= 3 x 3 min-max nodes covering the search window, weighted by the window
// texels in each, then pcss's filtering step; window edges on a texel
// boundary make a pixel ambiguous only when they change the result.
#include <gtest/gtest.h>

#include <cmath>

#include "fixtures.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {
namespace {

using testing::column_split_map;
using testing::pcss_minmax_variant;

Sample pcss_minmax_at(const FloatImage& map, const Query& q, const std::vector<Point2>& pcf,
                      const LightParams& light = {}) {
  return evaluate(pcss_minmax_variant(pcf), ShadowMapView(map), light, q);
}

// The NVIDIA PCSS whitepaper's light: the search width at z_r = 16 is L_uv (16 - 9.5) / 16,
// 0.0542 uv or 13.9 texels of 256.
TEST(PcssMinMax, NoBlockerIsFullyLitAndFullOcclusionBlack) {
  EXPECT_EQ(
      pcss_minmax_at(FloatImage(64, 64, 1, 20.0f), {0.5, 0.5, 16.0}, {{0.0f, 0.0f}}).visibility,
      1.0);
  EXPECT_EQ(
      pcss_minmax_at(FloatImage(64, 64, 1, 10.0f), {0.5, 0.5, 16.0}, {{0.0f, 0.0f}}).visibility,
      0.0);
}

TEST(PcssMinMax, BlockerDepthIsTheWindowWeightedMeanOfNodeMinima) {
  // Columns < 128 at z = 12, lit beyond, and one texel at z = 10 left of the
  // search window but inside a node that meets it.
  FloatImage map = column_split_map(256, 256, 128, 12.0f, 32.0f);
  map.at(98, 128) = 10.0f;
  const double z_r = 16.0, l_uv = 0.5 / 3.75, n = 9.5;
  const double u = 115.59 / 256;
  // The window [floor((u - w) W), floor((u + w) W)] is columns 101..129 and
  // rows 114..141: at level 4 it meets nodes 6..8 x 7..8 (at level 3, five
  // per axis). Blocking nodes: columns 96..111 (11 window columns, minima 12
  // and 10 in the two rows) and 112..127 (16 columns, 12 in both), each row
  // 14 window texels tall; columns 128..143 hold nothing nearer than 32.
  const double w = l_uv * (z_r - n) / z_r;
  ASSERT_EQ(int(std::floor((u - w) * 256)), 101);
  ASSERT_EQ(int(std::floor((u + w) * 256)), 129);
  const double z_b = (11 * 14 * (12.0 + 10.0) + 16 * 14 * (12.0 + 12.0)) / (2 * (11 + 16) * 14);
  const double radius = (z_r - z_b) / z_b * l_uv * n / z_r;
  // One PCF point (1.6, 0) lands between columns 127 (occluded) and 128.
  const float d = 1.6f;
  const double texel = (u + d * radius) * 256 - 0.5;
  ASSERT_GT(texel, 127.0);
  ASSERT_LT(texel, 128.0);
  EXPECT_NEAR(pcss_minmax_at(map, {u, 0.5, z_r}, {{d, 0.0f}}).visibility, texel - 127.0, 1e-5);
  // The nearest minimum alone (10) would give a wider radius: fully lit.
  const double nearest_radius = (z_r - 10.0) / 10.0 * l_uv * n / z_r;
  EXPECT_GT((u + d * nearest_radius) * 256 - 0.5, 128.0);
}

TEST(PcssMinMax, BlockersNearerThanTheNearPlaneCountAsOnIt) {
  // A blocker at z = 0 would make the penumbra (z_r - z_b) / z_b infinite;
  // it is taken at n = 9.5, the nearest depth a rendered map holds. The
  // radius is then the search width, 13.9 texels, and the PCF point
  // (-0.5, 0) from column 138 lands at 131.1, lit (a blocker at 5 taken as
  // it is would put it at 115.7, occluded).
  const std::vector<Point2> pcf = {{-0.5f, 0.0f}};
  for (const float depth : {0.0f, 5.0f, 9.5f}) {
    const FloatImage map = column_split_map(256, 256, 128, depth, 32.0f);
    EXPECT_EQ(pcss_minmax_at(map, {138.0 / 256, 0.5, 16.0}, pcf).visibility, 1.0) << "z " << depth;
  }
}

TEST(PcssMinMax, WindowOutsideTheMapFindsNoBlocker) {
  // Unlike point samples, the window does not clamp to the edge texels.
  EXPECT_EQ(
      pcss_minmax_at(FloatImage(64, 64, 1, 10.0f), {-0.5, 0.5, 16.0}, {{0.0f, 0.0f}}).visibility,
      1.0);
}

TEST(PcssMinMax, AmbiguousOnlyWhenAWindowEdgeChoiceChangesTheResult) {
  // Place the right window edge (u + w) W on texel boundary 128: x1 = 127
  // or 128. Only the second window meets column 140, which holds the one
  // blocker, at z = 10; its radius (12.2 texels) sends the PCF point (2.17,
  // 0) from column 114.1 to texel (140, 128), occluded.
  const double z_r = 16.0;
  const float w = float(0.5 / 3.75) * (float(z_r) - 9.5f) / float(z_r);
  const double u = double(0.5f - w);
  const double v = 128.5 / 256;
  ASSERT_NEAR((float(u) + w) * 256.0f, 128.0f, 1e-3);
  FloatImage map(256, 256, 1, 32.0f);
  map.at(140, 128) = 10.0f;
  EXPECT_EQ(pcss_minmax_at(map, {u, v, z_r}, {{2.17f, 0.0f}}).ambiguous,
            Ambiguity::search_window_edge);
  // The blocker changes, but a PCF point at the receiver is lit either way.
  EXPECT_EQ(pcss_minmax_at(map, {u, v, z_r}, {{0.0f, 0.0f}}).ambiguous, Ambiguity::none);
  // Away from the boundary nothing is ambiguous.
  EXPECT_EQ(pcss_minmax_at(map, {u + 0.3 / 256, v, z_r}, {{2.17f, 0.0f}}).ambiguous,
            Ambiguity::none);
}

TEST(CheckVariant, PcssMinMaxNeedsItsDisk) {
  EXPECT_TRUE(check_variant(pcss_minmax_variant({{0.0f, 0.0f}})));
  Variant variant = pcss_minmax_variant({{0.0f, 0.0f}});
  variant.keys.pcf_samples = 2;
  EXPECT_FALSE(check_variant(variant));
  variant.pcf_disk.reset();
  EXPECT_FALSE(check_variant(variant));
}

}  // namespace
}  // namespace penumbra::reference
