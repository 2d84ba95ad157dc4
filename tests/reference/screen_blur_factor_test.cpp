// screen_blur's factor pass (3x3 point-compare PCF with hard's ambiguity
// rule), its variant checks and its tolerance.
#include <gtest/gtest.h>

#include "fixtures.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {
namespace {

using testing::binomial5;
using testing::blur_variant;
using testing::column_split_map;

Sample factor(const FloatImage& map, double u, double v, double z = 10.0) {
  return evaluate(blur_variant(2, binomial5()), ShadowMapView(map), {}, {u, v, z});
}

TEST(ScreenBlurFactor, AllLitAndAllShadowed) {
  const FloatImage far(8, 8, 1, 20.0f);
  const FloatImage near(8, 8, 1, 5.0f);
  for (double u : {0.5 / 8, 3.5 / 8, 7.5 / 8}) {
    const Sample lit = factor(far, u, 4.5 / 8);
    EXPECT_EQ(lit.visibility, 1.0);
    EXPECT_EQ(lit.ambiguous, Ambiguity::none);
    const Sample shadowed = factor(near, u, 4.5 / 8);
    EXPECT_EQ(shadowed.visibility, 0.0);
    EXPECT_EQ(shadowed.ambiguous, Ambiguity::none);
  }
}

TEST(ScreenBlurFactor, CountsLitTexelsAcrossAnEdge) {
  // Columns 0-3 occlude. From texel 3's centre the columns read are 2, 3, 4:
  // one lit column of three; from texel 4's, 3, 4, 5: two.
  const FloatImage map = column_split_map(8, 8, 4, 5.0f, 20.0f);
  const Sample left = factor(map, 3.5 / 8, 4.5 / 8);
  EXPECT_DOUBLE_EQ(left.visibility, 3.0 / 9);
  EXPECT_EQ(left.ambiguous, Ambiguity::none);
  const Sample right = factor(map, 4.5 / 8, 4.5 / 8);
  EXPECT_DOUBLE_EQ(right.visibility, 6.0 / 9);
  EXPECT_EQ(right.ambiguous, Ambiguity::none);
}

TEST(ScreenBlurFactor, UsesTheBiasedDepth) {
  LightParams light;
  light.bias = 1.0;
  const FloatImage map(8, 8, 1, 9.5f);
  // z = 10 is behind 9.5, z - bias = 9 is not.
  EXPECT_EQ(factor(map, 0.5, 0.5).visibility, 0.0);
  EXPECT_EQ(evaluate(blur_variant(2, binomial5()), ShadowMapView(map), light, {0.5, 0.5, 10.0})
                .visibility,
            1.0);
}

TEST(ScreenBlurFactor, RowOffsetsAreTexelsOfTheHeight) {
  // 4 wide, 16 high, only row 8 lit. From row 7's centre the rows read are
  // 6, 7, 8: one lit row. Offsets of 1 / W (4 rows) would read 3, 7, 11: none.
  FloatImage map(4, 16, 1, 5.0f);
  for (int i = 0; i < 4; ++i) map.at(i, 8) = 20.0f;
  EXPECT_DOUBLE_EQ(factor(map, 0.3, 7.5 / 16).visibility, 3.0 / 9);
}

TEST(ScreenBlurFactor, ClampsAtTheMapEdge) {
  // Only column 0 lit: from its centre the column to its left clamps to it.
  const FloatImage map = column_split_map(8, 8, 1, 20.0f, 5.0f);
  EXPECT_DOUBLE_EQ(factor(map, 0.5 / 8, 4.5 / 8).visibility, 6.0 / 9);
}

TEST(ScreenBlurFactor, MarksAmbiguityOfAnyOfTheNineSamples) {
  const FloatImage map = column_split_map(8, 8, 4, 5.0f, 20.0f);
  // u W = 5: the centre sample sits on the 4|5 boundary (both lit), the left
  // column's on the 3|4 boundary (occluded | lit): ambiguous.
  EXPECT_EQ(factor(map, 5.0 / 8, 4.5 / 8).ambiguous, Ambiguity::texel_boundary);
  // u W = 6: boundaries 4|5, 5|6, 6|7, all lit on both sides.
  const Sample clear = factor(map, 6.0 / 8, 4.5 / 8);
  EXPECT_EQ(clear.ambiguous, Ambiguity::none);
  EXPECT_EQ(clear.visibility, 1.0);
  // Just inside the point window of the 3|4 boundary, and just outside it.
  const double window = SamplingPrecision{}.point_window();
  EXPECT_EQ(factor(map, (5.0 + 0.5 * window) / 8, 4.5 / 8).ambiguous, Ambiguity::texel_boundary);
  EXPECT_EQ(factor(map, (5.0 + 2.0 * window) / 8, 4.5 / 8).ambiguous, Ambiguity::none);
}

TEST(ScreenBlurFactor, EvaluateImageReturnsFactorAndMask) {
  const FloatImage map = column_split_map(8, 8, 4, 5.0f, 20.0f);
  FloatImage receivers(2, 1, 3);
  receivers.at(0, 0, 0) = 3.5f / 8;
  receivers.at(1, 0, 0) = 5.0f / 8;
  for (int i = 0; i < 2; ++i) receivers.at(i, 0, 1) = 4.5f / 8, receivers.at(i, 0, 2) = 10.0f;
  const auto result = evaluate_image(blur_variant(2, binomial5()), map, {}, receivers, {});
  ASSERT_TRUE(result.ok()) << result.error().to_string();
  EXPECT_EQ(result->visibility.at(0, 0), float(3.0 / 9));
  EXPECT_EQ(result->ambiguous.data, (std::vector<float>{0.0f, 1.0f}));
}

TEST(ScreenBlurCheckVariant, AcceptsValidWeights) {
  EXPECT_TRUE(check_variant(blur_variant(2, binomial5())));
  EXPECT_TRUE(check_variant(blur_variant(1, {0.25f, 0.5f, 0.25f}, true)));
}

TEST(ScreenBlurCheckVariant, RejectsBadRadiusAndWeights) {
  auto rejects = [](const Variant& variant, const std::string& fragment) {
    const auto status = check_variant(variant);
    ASSERT_FALSE(status.ok()) << fragment;
    EXPECT_NE(status.error().message.find(fragment), std::string::npos) << status.error().message;
  };
  Variant no_radius = blur_variant(2, binomial5());
  no_radius.keys.blur_radius.reset();
  rejects(no_radius, "blur_radius from 1 to 32");
  rejects(blur_variant(0, {1.0f}), "blur_radius from 1 to 32");
  rejects(blur_variant(33, std::vector<float>(67, 1.0f / 67)), "blur_radius from 1 to 32");
  rejects(blur_variant(1, binomial5()), "there are 5 blur weights, not 3");
  rejects(blur_variant(1, {-0.25f, 1.5f, -0.25f}), "positive");
  rejects(blur_variant(1, {0.0f, 1.0f, 0.0f}), "positive");
  rejects(blur_variant(1, {0.2f, 0.5f, 0.3f}), "symmetric");
  rejects(blur_variant(1, {0.25f, 0.5f, 0.2501f}), "symmetric");
  rejects(blur_variant(1, {0.25f, 0.51f, 0.25f}), "sum to");
  // Within 1e-5 of 1 passes.
  EXPECT_TRUE(check_variant(blur_variant(1, {0.25f, 0.500004f, 0.25f})));
}

TEST(ScreenBlurTolerance, IsHardsPointSampleTolerance) {
  EXPECT_EQ(tolerance(Technique::screen_blur, {}), tolerance(Technique::hard, {}));
  EXPECT_EQ(tolerance(Technique::screen_blur, {}), 1e-5);
}

}  // namespace
}  // namespace penumbra::reference
