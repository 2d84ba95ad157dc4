#include "penumbra/reference/compare.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

namespace penumbra::reference {
namespace {

// 10x10 images: reference all 0.5, GPU equal, no ambiguity.
struct Images {
  FloatImage gpu{10, 10, 1, 0.5f};
  FloatImage reference{10, 10, 1, 0.5f};
  FloatImage ambiguous{10, 10, 1, 0.0f};

  Comparison run(double tolerance = 0.01) const {
    auto result = compare(gpu, reference, ambiguous, tolerance);
    EXPECT_TRUE(result.ok());
    return result.ok() ? *result : Comparison{};
  }
};

TEST(Compare, EqualImagesPass) {
  const Comparison c = Images{}.run();
  EXPECT_TRUE(c.pass);
  EXPECT_EQ(c.pixels, 100u);
  EXPECT_EQ(c.compared, 100u);
  EXPECT_EQ(c.max_abs_error, 0.0);
}

TEST(Compare, OnePixelOverToleranceFails) {
  Images images;
  images.gpu.at(3, 4) = 0.52f;
  images.gpu.at(5, 5) = 0.505f;
  const Comparison c = images.run();
  EXPECT_FALSE(c.pass);
  EXPECT_EQ(c.over_tolerance, 1u);
  EXPECT_NEAR(c.max_abs_error, 0.02, 1e-6);
  EXPECT_NEAR(c.mean_abs_error, 0.025 / 100, 1e-7);
}

TEST(Compare, NanFails) {
  Images images;
  images.gpu.at(0, 0) = std::numeric_limits<float>::quiet_NaN();
  const Comparison c = images.run();
  EXPECT_FALSE(c.pass);
  EXPECT_EQ(c.over_tolerance, 1u);
  EXPECT_TRUE(std::isinf(c.max_abs_error));
}

TEST(Compare, AmbiguousPixelsAreSkippedUpToTheLimit) {
  Images images;
  images.gpu.at(1, 1) = 1.0f;
  images.gpu.at(2, 2) = 0.0f;
  images.ambiguous.at(1, 1) = 1.0f;
  images.ambiguous.at(2, 2) = 1.0f;
  Comparison c = images.run();
  EXPECT_TRUE(c.pass);  // 2 of 100 is the limit
  EXPECT_EQ(c.ambiguous, 2u);
  EXPECT_EQ(c.compared, 98u);
  EXPECT_EQ(c.max_abs_error, 0.0);

  images.ambiguous.at(3, 3) = 1.0f;  // 3% is too many
  c = images.run();
  EXPECT_FALSE(c.pass);
  EXPECT_EQ(c.over_tolerance, 0u);
}

TEST(Compare, SizesMustMatch) {
  Images images;
  images.reference = FloatImage(10, 9, 1, 0.5f);
  const auto result = compare(images.gpu, images.reference, images.ambiguous, 0.01);
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.error().message.find("reference 10x9"), std::string::npos);
}

TEST(Compare, ToJson) {
  Images images;
  images.gpu.at(0, 0) = 0.75f;
  const nlohmann::json json = images.run();
  EXPECT_EQ(json.at("pixels"), 100);
  EXPECT_EQ(json.at("over_tolerance"), 1);
  EXPECT_EQ(json.at("pass"), false);
  EXPECT_DOUBLE_EQ(json.at("max_abs_error").get<double>(), 0.25);
  EXPECT_DOUBLE_EQ(json.at("tolerance").get<double>(), 0.01);
  for (const char* key : {"compared", "ambiguous", "mean_abs_error"})
    EXPECT_TRUE(json.contains(key));
}

}  // namespace
}  // namespace penumbra::reference
