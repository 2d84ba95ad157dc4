// The shaders' stack-free walk (shaderlib/common/minmax_traversal.glsl),
// as the reference's MinmaxCursor takes it in count_occluders(): it counts
// exactly the texels brute force counts within the shader's bounds
// (minmax_max_visits(), minmax_max_steps()), a walk a target caps counts
// what its steps reached, and one that descends only where it then still
// ends within them always ends.
#include "penumbra/reference/minmax_cursor.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "penumbra/model/model.hpp"
#include "penumbra/reference/minmax_mip.hpp"
#include "penumbra/reference/minmax_pcf.hpp"

namespace penumbra::reference {
namespace {

// The nodes the walk reads, each checked to lie inside its level.
void expect_reads_inside_levels(const MinMaxMip& mip, const TexelRect& window) {
  for (MinmaxCursor cursor(window); !cursor.done();) {
    const bool reads = !cursor.climbed() && !intersect(cursor.texels(), window).empty();
    if (reads) {
      ASSERT_TRUE(cursor.x() < mip.width(cursor.level()) && cursor.y() < mip.height(cursor.level()))
          << "read outside level " << cursor.level();
    }
    const bool descend = reads && cursor.level() > 0 && cursor.x() % 3 == 0;  // any pattern
    if (descend) {
      cursor.descend();
    } else {
      cursor.next();
    }
  }
}

// Maps that make the walk descend: a checkerboard (every node above level 0
// straddles a reference of 0.5) and random blocks.
FloatImage checkerboard(int width, int height) {
  FloatImage map(width, height, 1);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) map.at(x, y) = (x + y) % 2 == 0 ? 0.25f : 0.75f;
  }
  return map;
}

FloatImage blocks(int width, int height, std::mt19937& random) {
  std::uniform_int_distribution<int> size(1, 9);
  std::uniform_real_distribution<float> value(0.0f, 1.0f);
  FloatImage map(width, height, 1, 1.0f);
  for (int n = 0; n < width * height / 8 + 1; ++n) {
    const int x0 = static_cast<int>(value(random) * static_cast<float>(width));
    const int y0 = static_cast<int>(value(random) * static_cast<float>(height));
    const int w = size(random), h = size(random);
    const float d = value(random);
    for (int y = y0; y < std::min(height, y0 + h); ++y) {
      for (int x = x0; x < std::min(width, x0 + w); ++x) map.at(x, y) = d;
    }
  }
  return map;
}

TEST(MinmaxCursor, CountsExactlyWithinTheBoundsAndACapStopsIt) {
  std::mt19937 random(4);
  std::vector<FloatImage> maps;
  for (auto [w, h] : std::vector<std::array<int, 2>>{
           {1, 1}, {3, 5}, {16, 16}, {37, 23}, {64, 64}, {129, 70}, {200, 200}}) {
    maps.push_back(checkerboard(w, h));
    maps.push_back(blocks(w, h, random));
  }
  std::vector<MinMaxMip> mips;
  for (const FloatImage& map : maps) mips.emplace_back(ShadowMapView(map));
  std::uniform_real_distribution<float> unit(-0.2f, 1.2f);
  int most_steps_at_128 = 0;
  int truncated = 0;
  for (int kernel = 1; kernel <= 128; ++kernel) {
    for (std::size_t m = 0; m < maps.size(); ++m) {
      const ShadowMapView map(maps[m]);
      for (int sample = 0; sample < 12; ++sample) {
        // The shader's window: floor(u W) - floor(K / 2) .. + K - 1, clipped.
        const int cx = static_cast<int>(std::floor(unit(random) * static_cast<float>(map.width())));
        const int cy =
            static_cast<int>(std::floor(unit(random) * static_cast<float>(map.height())));
        const TexelRect window = clip({cx - kernel / 2, cy - kernel / 2,
                                       cx - kernel / 2 + kernel - 1, cy - kernel / 2 + kernel - 1},
                                      map.width(), map.height());
        if (window.empty()) continue;
        expect_reads_inside_levels(mips[m], window);
        const float reference = sample % 3 == 0 ? 0.5f : unit(random);
        const MipCount walk = count_occluders(mips[m], window, reference);
        ASSERT_FALSE(walk.truncated);
        ASSERT_LE(walk.visits, minmax_max_visits(kernel)) << "K " << kernel;
        ASSERT_LE(walk.steps, minmax_max_steps(kernel)) << "K " << kernel;
        ASSERT_EQ(walk.count, count_occluders_brute_force(map, window, reference))
            << "K " << kernel;
        if (kernel == 128) most_steps_at_128 = std::max(most_steps_at_128, walk.steps);
        // Capped one step short, the walk stops there with part of the count.
        if (walk.steps < 2) continue;
        const MipCount capped = count_occluders(mips[m], window, reference, walk.steps - 1);
        ASSERT_TRUE(capped.truncated);
        ASSERT_EQ(capped.steps, walk.steps - 1);
        ASSERT_LE(capped.count, walk.count);
        ++truncated;
      }
    }
  }
  // The walk does use a good part of the bound: it is not vacuous.
  EXPECT_GT(most_steps_at_128 * 2, minmax_max_steps(128));
  EXPECT_GT(truncated, 1000);
}

// The steps a walk takes from a node if it descends no further: exactly
// steps_to_end(), from anywhere in a walk that descends any pattern.
TEST(MinmaxCursor, StepsToEndCountsTheRestOfAWalkThatDescendsNoFurther) {
  std::mt19937 random(9);
  std::uniform_int_distribution<int> corner(0, 299), side(1, 300), coin(0, 2);
  for (int sample = 0; sample < 300; ++sample) {
    const int x0 = corner(random), y0 = corner(random);
    const TexelRect window = clip({x0, y0, x0 + side(random), y0 + side(random)}, 300, 300);
    for (MinmaxCursor cursor(window); !cursor.done();) {
      MinmaxCursor rest = cursor;
      int steps = 0;
      for (; !rest.done(); ++steps) rest.next();
      ASSERT_EQ(steps, cursor.steps_to_end()) << "window from " << x0 << ", " << y0;
      const bool reads = !cursor.climbed() && !intersect(cursor.texels(), window).empty();
      if (reads && cursor.level() > 0 && coin(random) > 0) {
        cursor.descend();
      } else {
        cursor.next();
      }
    }
  }
}

// backprojection's walk under a target's cap (BACKPROJECTION_FINISH_COARSE)
// descends only where it still ends within its n steps: it always ends, and
// where the walk that descends wherever it wants takes at most n steps, it
// is that walk. Here every node read wants refining.
TEST(MinmaxCursor, AWalkThatDescendsOnlyWhereItStillEndsIsWholeWhereThatFits) {
  std::mt19937 random(9);
  std::uniform_int_distribution<int> corner(0, 511), side(1, 64);
  auto wants = [](const MinmaxCursor& cursor, const TexelRect& window) {
    return !cursor.climbed() && !intersect(cursor.texels(), window).empty() && cursor.level() > 0;
  };
  int whole = 0, finished = 0;
  for (int sample = 0; sample < 400; ++sample) {
    const int x0 = corner(random), y0 = corner(random);
    const TexelRect window = clip({x0, y0, x0 + side(random), y0 + side(random)}, 512, 512);
    int uncapped = 0;
    for (MinmaxCursor cursor(window); !cursor.done(); ++uncapped) {
      if (wants(cursor, window)) {
        cursor.descend();
      } else {
        cursor.next();
      }
    }
    for (int steps : {4, 5, 31, 224, 1000}) {
      MinmaxCursor cursor(window);
      int step = 0;
      bool refused = false;
      for (; step < steps && !cursor.done(); ++step) {
        if (wants(cursor, window) && cursor.steps_to_end() + 4 <= steps - step - 1) {
          cursor.descend();
        } else {
          refused = refused || wants(cursor, window);
          cursor.next();
        }
      }
      ASSERT_TRUE(cursor.done()) << steps << " steps, window from " << x0 << ", " << y0;
      ASSERT_EQ(refused, uncapped > steps) << steps << " steps, window from " << x0 << ", " << y0;
      if (!refused) {
        ASSERT_EQ(step, uncapped);
      }
      whole += !refused;
      finished += refused;
    }
  }
  EXPECT_GT(whole, 100);
  EXPECT_GT(finished, 1000);
}

// Brute force capped after n texels counts the first n in rows.
TEST(MinmaxCursor, BruteForceCapCountsTheFirstTexelsInRows) {
  FloatImage image(4, 4, 1, 1.0f);
  image.at(3, 0) = 0.0f;
  image.at(0, 1) = 0.0f;
  const ShadowMapView map(image);
  EXPECT_EQ(count_occluders_brute_force(map, {0, 0, 3, 3}, 0.5f, 3), 0);
  EXPECT_EQ(count_occluders_brute_force(map, {0, 0, 3, 3}, 0.5f, 4), 1);
  EXPECT_EQ(count_occluders_brute_force(map, {0, 0, 3, 3}, 0.5f, 5), 2);
  EXPECT_EQ(count_occluders_brute_force(map, {0, 0, 3, 3}, 0.5f), 2);
}

}  // namespace
}  // namespace penumbra::reference
