// The min-max mip's level sizes: each level halves the one below rounding
// up, the top one is 1x1, and the square chain that stores them is large
// enough for every level (docs/shader-interface.md, "The min-max mip").
#include "penumbra/support/minmax_levels.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace penumbra {
namespace {

struct Expected {
  int width;
  int height;
  int top_level;
  int chain_side;
  std::vector<LevelSize> sizes;  // levels 1..N
};

void expect_levels(const Expected& e) {
  SCOPED_TRACE(std::to_string(e.width) + "x" + std::to_string(e.height));
  EXPECT_EQ(minmax_top_level(e.width, e.height), e.top_level);
  EXPECT_EQ(minmax_chain_side(e.width, e.height), e.chain_side);
  const std::vector<LevelSize> sizes = minmax_level_sizes(e.width, e.height);
  ASSERT_EQ(sizes.size(), e.sizes.size());
  LevelSize below{e.width, e.height};
  for (std::size_t m = 0; m < sizes.size(); ++m) {
    EXPECT_EQ(sizes[m].width, e.sizes[m].width) << "level " << m + 1;
    EXPECT_EQ(sizes[m].height, e.sizes[m].height) << "level " << m + 1;
    // Each level covers the one below, and fits in mip m of the chain.
    EXPECT_GE(2 * sizes[m].width, below.width) << "level " << m + 1;
    EXPECT_GE(2 * sizes[m].height, below.height) << "level " << m + 1;
    EXPECT_LE(sizes[m].width, e.chain_side >> m) << "level " << m + 1;
    EXPECT_LE(sizes[m].height, e.chain_side >> m) << "level " << m + 1;
    below = sizes[m];
  }
  EXPECT_EQ(sizes.back().width, 1);
  EXPECT_EQ(sizes.back().height, 1);
}

TEST(MinMaxLevels, SizesTopLevelAndChainSide) {
  // Even a 1x1 map has one level above it.
  expect_levels({1, 1, 1, 1, {{1, 1}}});
  expect_levels({1, 7, 3, 4, {{1, 4}, {1, 2}, {1, 1}}});
  expect_levels({5, 3, 3, 4, {{3, 2}, {2, 1}, {1, 1}}});
  expect_levels({250,
                 190,
                 8,
                 128,
                 {{125, 95}, {63, 48}, {32, 24}, {16, 12}, {8, 6}, {4, 3}, {2, 2}, {1, 1}}});
  expect_levels({256,
                 256,
                 8,
                 128,
                 {{128, 128}, {64, 64}, {32, 32}, {16, 16}, {8, 8}, {4, 4}, {2, 2}, {1, 1}}});
  expect_levels({257,
                 1,
                 9,
                 256,
                 {{129, 1}, {65, 1}, {33, 1}, {17, 1}, {9, 1}, {5, 1}, {3, 1}, {2, 1}, {1, 1}}});
}

TEST(MinMaxLevels, SizeVec4HoldsSizeAndReciprocal) {
  const std::array<float, 4> v = size_vec4(250, 4);
  EXPECT_EQ(v[0], 250.0f);
  EXPECT_EQ(v[1], 4.0f);
  EXPECT_EQ(v[2], 1.0f / 250.0f);
  EXPECT_EQ(v[3], 0.25f);
}

}  // namespace
}  // namespace penumbra
