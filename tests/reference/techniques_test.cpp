// pcf_grid and pcf_poisson on hand-built maps, variant checks and
// whole-image evaluation.
#include "penumbra/reference/techniques.hpp"

#include <gtest/gtest.h>

#include "fixtures.hpp"

namespace penumbra::reference {
namespace {

using testing::column_split_map;
using testing::grid_variant;
using testing::poisson_variant;

// 8x8, columns 0-3 at depth 5 occlude a receiver at z = 10, columns 4-7 do not.
const FloatImage& half_occluded() {
  static const FloatImage map = column_split_map(8, 8, 4, 5.0f, 20.0f);
  return map;
}

double visibility(const Variant& variant, double u, const LightParams& light = {}) {
  return evaluate(variant, ShadowMapView(half_occluded()), light, {u, 0.4, 10.0}).visibility;
}

TEST(PcfGrid, HalfOccludedMap) {
  // u = 0.5 is x = u W - 0.5 = 3.5: the 3x3 kernel reads x = 2.5 (0),
  // 3.5 (0.5) and 4.5 (1) in every row.
  EXPECT_DOUBLE_EQ(visibility(grid_variant(3), 0.5), 0.5);
  // x = 3.75: 2.75 -> 0, 3.75 -> 0.75, 4.75 -> 1.
  EXPECT_DOUBLE_EQ(visibility(grid_variant(3), 3.75 / 8 + 0.5 / 8), 1.75 / 3);
  // K = 5 at x = 3.75: 0, 0, 0.75, 1, 1.
  EXPECT_DOUBLE_EQ(visibility(grid_variant(5), 4.25 / 8), 2.75 / 5);
  EXPECT_DOUBLE_EQ(visibility(grid_variant(3), 0.1), 0.0);
  EXPECT_DOUBLE_EQ(visibility(grid_variant(3), 0.9), 1.0);
}

TEST(PcfGrid, OffsetsAreWholeTexelsOnEachAxis) {
  // 4 wide, 8 high, only row 4 lit. At y = v H - 0.5 = 3.75 the kernel's rows
  // read y = 2.75 (0), 3.75 (0.75) and 4.75 (0.25): one texel of H apart.
  FloatImage map(4, 8, 1, 5.0f);
  for (int i = 0; i < 4; ++i) map.at(i, 4) = 20.0f;
  const Sample s = evaluate(grid_variant(3), ShadowMapView(map), {}, {0.3, 4.25 / 8, 10.0});
  EXPECT_DOUBLE_EQ(s.visibility, 1.0 / 3);
}

TEST(PcfGrid, KernelOneIsOneBilinearComparison) {
  EXPECT_DOUBLE_EQ(visibility(grid_variant(1), 3.75 / 8 + 0.5 / 8), 0.75);
}

TEST(PcfPoisson, ScalesTheDiskByTheFilterRadius) {
  const Variant variant = poisson_variant({{1.0f, 0.0f}, {-1.0f, 0.0f}});
  LightParams light;
  light.filter_radius_uv = 1.0 / 8;
  // From x = 3.5 the two points land on x = 4.5 (lit) and 2.5 (occluded).
  EXPECT_DOUBLE_EQ(visibility(variant, 0.5, light), 0.5);
}

TEST(PcfPoisson, DefaultFilterRadiusIsTwoTexels) {
  const Variant variant = poisson_variant({{1.0f, 0.0f}});
  // u = 0.25 plus 2 texels is u = 0.5: x = 3.5, halfway.
  EXPECT_DOUBLE_EQ(visibility(variant, 0.25), 0.5);
  LightParams light;
  light.filter_radius_uv = 1.0 / 8;
  EXPECT_DOUBLE_EQ(visibility(variant, 0.25, light), 0.0);
}

TEST(CheckVariant, NamesWhatIsMissing) {
  EXPECT_TRUE(check_variant(grid_variant(3)));
  const auto even = check_variant(grid_variant(4));
  ASSERT_FALSE(even.ok());
  EXPECT_NE(even.error().message.find("odd"), std::string::npos);

  Variant short_disk = poisson_variant({{0.0f, 0.0f}});
  short_disk.keys.pcf_samples = 16;
  const auto mismatch = check_variant(short_disk);
  ASSERT_FALSE(mismatch.ok());
  EXPECT_EQ(mismatch.error().message, "pcf_samples is 16 but the pcf disk has 1 points");

  Variant no_disk = testing::pcss_variant({{0.0f, 0.0f}}, {{0.0f, 0.0f}});
  no_disk.blocker_disk.reset();
  EXPECT_FALSE(check_variant(no_disk).ok());
}

TEST(EvaluateImage, EvaluatesEveryReceiver) {
  FloatImage receivers(3, 2, 4);
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 3; ++i) {
      receivers.at(i, j, 0) = float(0.125 + 0.375 * i);  // x = 0.5, 3.5, 6.5
      receivers.at(i, j, 1) = 0.5f;
      receivers.at(i, j, 2) = 10.0f;
    }
  }
  const auto result =
      evaluate_image(grid_variant(1), half_occluded(), LightParams{}, receivers, {});
  ASSERT_TRUE(result.ok()) << result.error().to_string();
  ASSERT_EQ(result->visibility.width, 3);
  ASSERT_EQ(result->visibility.height, 2);
  EXPECT_EQ(result->visibility.at(0, 1), 0.0f);
  EXPECT_EQ(result->visibility.at(1, 1), 0.5f);
  EXPECT_EQ(result->visibility.at(2, 1), 1.0f);
  EXPECT_EQ(result->ambiguous.data, std::vector<float>(6, 0.0f));
}

TEST(EvaluateImage, MarksAmbiguousPixels) {
  FloatImage receivers(2, 1, 3);
  receivers.at(0, 0, 0) = 0.5f;  // on the boundary between texels 3 and 4
  receivers.at(1, 0, 0) = 0.3f;
  for (int i = 0; i < 2; ++i) receivers.at(i, 0, 1) = 0.5f, receivers.at(i, 0, 2) = 10.0f;
  const auto result =
      evaluate_image(testing::hard_variant(), half_occluded(), LightParams{}, receivers, {});
  ASSERT_TRUE(result.ok()) << result.error().to_string();
  EXPECT_EQ(result->ambiguous.data, (std::vector<float>{1.0f, 0.0f}));
}

TEST(EvaluateImage, RejectsWrongChannelCounts) {
  const auto bad_receivers =
      evaluate_image(grid_variant(1), half_occluded(), LightParams{}, FloatImage(2, 2, 1), {});
  ASSERT_FALSE(bad_receivers.ok());
  EXPECT_EQ(bad_receivers.error().where, "receivers");
  const auto bad_map =
      evaluate_image(grid_variant(1), FloatImage(2, 2, 3), LightParams{}, FloatImage(2, 2, 3), {});
  ASSERT_FALSE(bad_map.ok());
  EXPECT_EQ(bad_map.error().where, "shadow map");
}

// Receivers across the half-occluded map at x = 0.5, 3.5 and 6.5 texels,
// moved `dx` texels right.
FloatImage row_of_receivers(double dx) {
  FloatImage receivers(3, 2, 3);
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 3; ++i) {
      receivers.at(i, j, 0) = float((0.5 + 3.0 * i + dx) / 8);
      receivers.at(i, j, 1) = 0.5f;
      receivers.at(i, j, 2) = 10.0f;
    }
  }
  return receivers;
}

TEST(EvaluateVisibility, EachImageAtTheGivenPixelsAsEvaluateImage) {
  const std::vector<FloatImage> receivers{row_of_receivers(0.0), row_of_receivers(0.25),
                                          row_of_receivers(-0.25)};
  const std::vector<std::size_t> pixels{1, 3, 4};
  for (const Variant& variant : {grid_variant(3), testing::minmax_pcf_variant(3)}) {
    SCOPED_TRACE(variant.name);
    const auto some = evaluate_visibility(variant, ShadowMapView(half_occluded()), LightParams{},
                                          receivers, pixels);
    ASSERT_TRUE(some.ok()) << some.error().to_string();
    ASSERT_EQ(some->size(), receivers.size());
    for (std::size_t r = 0; r < receivers.size(); ++r) {
      const auto whole = evaluate_image(variant, half_occluded(), LightParams{}, receivers[r]);
      ASSERT_TRUE(whole.ok()) << whole.error().to_string();
      for (std::size_t k = 0; k < 6; ++k) {
        const bool asked = k == 1 || k == 3 || k == 4;
        EXPECT_EQ((*some)[r].data[k], asked ? whole->visibility.data[k] : 0.0f)
            << "image " << r << ", pixel " << k;
      }
    }
  }
}

TEST(EvaluateVisibility, RejectsImagesOfDifferentSizesAndPixelsOutside) {
  const ShadowMapView map(half_occluded());
  const std::vector<FloatImage> mixed{row_of_receivers(0.0), FloatImage(2, 2, 3)};
  const std::vector<std::size_t> first{0};
  const auto sizes = evaluate_visibility(grid_variant(1), map, LightParams{}, mixed, first);
  ASSERT_FALSE(sizes.ok());
  EXPECT_EQ(sizes.error().where, "receivers");
  const std::vector<FloatImage> one{row_of_receivers(0.0)};
  const std::vector<std::size_t> outside{6};
  const auto index = evaluate_visibility(grid_variant(1), map, LightParams{}, one, outside);
  ASSERT_FALSE(index.ok());
  EXPECT_EQ(index.error().where, "pixels");
}

}  // namespace
}  // namespace penumbra::reference
