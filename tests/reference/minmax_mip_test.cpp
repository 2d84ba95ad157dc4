// The CPU min-max mip: level sizes by the design's rule for square, non-square
// and non-power-of-two maps, and every node against a brute-force min/max of
// the map texels it covers.
#include "penumbra/reference/minmax_mip.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "fixtures.hpp"

namespace penumbra::reference {
namespace {

struct MapSize {
  int width;
  int height;
  int top_level;  // N = max(1, ceil(log2(max(W, H)))), worked out by hand
};

class MinMaxMipSizes : public ::testing::TestWithParam<MapSize> {};

TEST_P(MinMaxMipSizes, LevelsHalveRoundingUpToOneByOne) {
  const MapSize size = GetParam();
  const FloatImage map = testing::random_map(size.width, size.height, 1.0f, 2.0f, 7);
  const MinMaxMip mip{ShadowMapView(map)};
  ASSERT_EQ(mip.top_level(), size.top_level);
  EXPECT_EQ(mip.width(0), size.width);
  EXPECT_EQ(mip.height(0), size.height);
  for (int level = 1; level <= mip.top_level(); ++level) {
    EXPECT_EQ(mip.width(level), (mip.width(level - 1) + 1) / 2) << "level " << level;
    EXPECT_EQ(mip.height(level), (mip.height(level - 1) + 1) / 2) << "level " << level;
  }
  EXPECT_EQ(mip.width(mip.top_level()), 1);
  EXPECT_EQ(mip.height(mip.top_level()), 1);
}

TEST_P(MinMaxMipSizes, EveryNodeIsTheMinMaxOfItsTexelBlock) {
  const MapSize size = GetParam();
  const FloatImage map = testing::random_map(size.width, size.height, 1.0f, 2.0f, 11);
  const MinMaxMip mip{ShadowMapView(map)};
  for (int level = 0; level <= mip.top_level(); ++level) {
    const int block = 1 << level;
    for (int j = 0; j < mip.height(level); ++j) {
      for (int i = 0; i < mip.width(level); ++i) {
        // [i 2^l, (i+1) 2^l) x [j 2^l, (j+1) 2^l) clipped to the map.
        const int x_end = std::min((i + 1) * block, size.width);
        const int y_end = std::min((j + 1) * block, size.height);
        ASSERT_LT(i * block, x_end);
        ASSERT_LT(j * block, y_end);
        float lo = map.at(i * block, j * block), hi = lo;
        for (int y = j * block; y < y_end; ++y) {
          for (int x = i * block; x < x_end; ++x) {
            lo = std::min(lo, map.at(x, y));
            hi = std::max(hi, map.at(x, y));
          }
        }
        const MinMax node = mip.node(level, i, j);
        ASSERT_EQ(node.min, lo) << "level " << level << " node " << i << ", " << j;
        ASSERT_EQ(node.max, hi) << "level " << level << " node " << i << ", " << j;
        const TexelRect extent = mip.extent(level, i, j);
        EXPECT_EQ(extent.x0, i * block);
        EXPECT_EQ(extent.y0, j * block);
        EXPECT_EQ(extent.x1, x_end - 1);
        EXPECT_EQ(extent.y1, y_end - 1);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, MinMaxMipSizes,
                         ::testing::Values(MapSize{1, 1, 1}, MapSize{1, 7, 3}, MapSize{7, 1, 3},
                                           MapSize{5, 3, 3}, MapSize{2, 2, 1}, MapSize{3, 129, 8},
                                           MapSize{250, 190, 8}, MapSize{256, 256, 8}),
                         [](const auto& param_info) {
                           return std::to_string(param_info.param.width) + "x" +
                                  std::to_string(param_info.param.height);
                         });

TEST(StartLevel, IsTheFirstLevelWhereTheWindowSpansTwoNodes) {
  EXPECT_EQ(start_level({5, 5, 5, 5}), 0);
  EXPECT_EQ(start_level({5, 5, 6, 6}), 0);
  EXPECT_EQ(start_level({5, 5, 7, 5}), 1);  // 2 .. 3 at level 1
  EXPECT_EQ(start_level({7, 0, 8, 0}), 0);
  EXPECT_EQ(start_level({7, 0, 9, 0}), 1);  // 3 .. 4 at level 1
  EXPECT_EQ(start_level({0, 0, 0, 9}), 3);  // rows 0 .. 1 at level 3, 0 .. 2 at level 2
  EXPECT_EQ(start_level({63, 0, 64, 0}), 0);
  EXPECT_EQ(start_level({62, 0, 65, 0}), 1);  // 31 .. 32 at level 1
  EXPECT_EQ(start_level({56, 0, 71, 0}), 3);  // 14 .. 17 at level 2, 7 .. 8 at level 3
}

}  // namespace
}  // namespace penumbra::reference
