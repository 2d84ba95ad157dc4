// The references a pair's pictures are judged against, shared by inputs:
// equal inputs evaluate once and get the same image, and any input that
// differs (a receiver's last bit, the map, the light) evaluates anew.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "penumbra/verify/stage_picture.hpp"

namespace penumbra::testing {
namespace {

// An 8x8 linear map, its left half at depth 5, and receivers across it at z = 10.
EngineMap half_occluded() {
  EngineMap map{FloatImage(8, 8, 1, 20.0f), std::nullopt, 1.0};
  for (int j = 0; j < 8; ++j) {
    for (int i = 0; i < 4; ++i) map.stored.at(i, j) = 5.0f;
  }
  return map;
}

FloatImage receivers() {
  FloatImage out(4, 2, 3);
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 4; ++i) {
      out.at(i, j, 0) = float(0.1 + 0.25 * i);
      out.at(i, j, 1) = 0.5f;
      out.at(i, j, 2) = 10.0f;
    }
  }
  return out;
}

Variant hard() {
  Variant v;
  v.name = "hard";
  v.technique = Technique::hard;
  return v;
}

TEST(PictureReferences, EqualInputsEvaluateOnceAndGetTheSameImage) {
  PictureReferences references;
  const EngineMap map = half_occluded();
  const FloatImage at = receivers();
  const auto first = references.get(hard(), map, LightParams{}, at, {}, {});
  ASSERT_TRUE(first) << first.error().to_string();
  const auto again = references.get(hard(), half_occluded(), LightParams{}, receivers(), {}, {});
  ASSERT_TRUE(again) << again.error().to_string();
  EXPECT_EQ(references.evaluated(), 1u);
  EXPECT_EQ(again->visibility.data, first->visibility.data);
  EXPECT_EQ(first->visibility.data, (std::vector<float>{0, 0, 1, 1, 0, 0, 1, 1}));
}

TEST(PictureReferences, AnyInputThatDiffersEvaluatesAnew) {
  PictureReferences references;
  const EngineMap map = half_occluded();
  ASSERT_TRUE(references.get(hard(), map, LightParams{}, receivers(), {}, {}));
  FloatImage moved = receivers();
  moved.at(1, 0, 0) = std::nextafter(moved.at(1, 0, 0), 1.0f);
  ASSERT_TRUE(references.get(hard(), map, LightParams{}, moved, {}, {}));
  EngineMap other = map;
  other.stored.at(7, 7) = 19.0f;
  ASSERT_TRUE(references.get(hard(), other, LightParams{}, receivers(), {}, {}));
  LightParams light;
  light.bias = 0.5;
  ASSERT_TRUE(references.get(hard(), map, light, receivers(), {}, {}));
  EXPECT_EQ(references.evaluated(), 4u);
}

}  // namespace
}  // namespace penumbra::testing
