// Shadow map upload and readback.
#include <gtest/gtest.h>

#include <string>

#include "test_programs.hpp"

namespace penumbra {
namespace {

TEST(ShadowMapTest, UploadThenReadBackIsExact) {
  auto engine = test::make_engine();
  ASSERT_NE(engine, nullptr);
  // Not square, so a transposed copy would show; values with full mantissas.
  FloatImage depth(7, 5, 1);
  for (int j = 0; j < depth.height; ++j) {
    for (int i = 0; i < depth.width; ++i)
      depth.at(i, j) = static_cast<float>(i * 5 + j + 1) / 37.0f;
  }
  depth.at(0, 0) = 0.0f;
  depth.at(6, 4) = 1.0f;

  auto map = engine->upload_shadow_map(depth);
  ASSERT_TRUE(map) << map.error().to_string();
  EXPECT_EQ((*map)->width(), 7);
  EXPECT_EQ((*map)->height(), 5);
  auto back = engine->read_shadow_map(**map);
  ASSERT_TRUE(back) << back.error().to_string();
  EXPECT_EQ(back->width, 7);
  EXPECT_EQ(back->height, 5);
  EXPECT_EQ(back->channels, 1);
  EXPECT_EQ(back->data, depth.data);
}

TEST(ShadowMapTest, DepthOutsideZeroOneIsRefused) {
  auto engine = test::make_engine();
  ASSERT_NE(engine, nullptr);
  FloatImage depth(4, 3, 1, 0.5f);
  depth.at(2, 1) = 1.5f;
  auto map = engine->upload_shadow_map(depth);
  ASSERT_FALSE(map);
  EXPECT_EQ(map.error().kind, Error::Kind::bad_input);
  EXPECT_NE(map.error().message.find("texel (2, 1) is 1.5"), std::string::npos)
      << map.error().message;
}

TEST(ShadowMapTest, EmptyOrMultiChannelImagesAreRefused) {
  auto engine = test::make_engine();
  ASSERT_NE(engine, nullptr);
  EXPECT_FALSE(engine->upload_shadow_map(FloatImage(0, 4, 1)));
  auto three = engine->upload_shadow_map(FloatImage(4, 4, 3, 0.5f));
  ASSERT_FALSE(three);
  EXPECT_NE(three.error().message.find("expected one channel"), std::string::npos);
}

TEST(ShadowMapTest, AMapWorksOnlyWithItsOwnEngine) {
  auto first = test::make_engine();
  auto second = test::make_engine();
  ASSERT_NE(first, nullptr);
  ASSERT_NE(second, nullptr);
  auto map = first->upload_shadow_map(FloatImage(2, 2, 1, 0.25f));
  ASSERT_TRUE(map) << map.error().to_string();
  auto read = second->read_shadow_map(**map);
  ASSERT_FALSE(read);
  EXPECT_NE(read.error().message.find("different Engine"), std::string::npos);
}

TEST(ShadowMapTest, AMapMayOutliveItsEngine) {
  auto engine = test::make_engine();
  ASSERT_NE(engine, nullptr);
  auto map = engine->upload_shadow_map(FloatImage(2, 2, 1, 0.25f));
  ASSERT_TRUE(map) << map.error().to_string();
  std::shared_ptr<ShadowMap> kept = *map;
  engine.reset();
  EXPECT_EQ(kept->width(), 2);
}

}  // namespace
}  // namespace penumbra
