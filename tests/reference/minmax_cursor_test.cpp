// The stack-free walk of shaderlib/common/minmax_traversal.glsl, simulated
// on the CPU step for step (same start level, roots, child order and cursor
// steps as MinmaxCursor): over the reference's MinMaxMip it visits the same
// nodes as the reference's count_occluders(), never more than the shader's
// loop bound MINMAX_MAX_VISITS (minmax_max_visits()), and counts exactly the
// texels brute force counts.
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

// The shader's MinmaxCursor (node coordinates are exact integers there too).
struct Cursor {
  int x = 0, y = 0, level = 0, span = 1, first_x = 0, first_y = 0, start = 0;
  bool done = false;

  explicit Cursor(const TexelRect& w) {
    for (int k = 0; k < 16; ++k) {  // MINMAX_MAX_LEVEL
      if (std::max(w.x1 / span - w.x0 / span, w.y1 / span - w.y0 / span) <= 1) break;
      ++level;
      span *= 2;
    }
    start = level;
    first_x = x = w.x0 / span;
    first_y = y = w.y0 / span;
  }
  void descend() {
    x *= 2;
    y *= 2;
    --level;
    span /= 2;
  }
  // minmax_next: to the next sibling, climbing while the node is the last.
  void next() {
    for (int k = 0; k <= 16; ++k) {  // MINMAX_MAX_LEVEL + 1
      const bool root = level >= start;
      const int sx = root ? first_x : x / 2 * 2;
      const int sy = root ? first_y : y / 2 * 2;
      if (x == sx) {
        ++x;
        return;
      }
      if (y == sy) {
        x = sx;
        ++y;
        return;
      }
      if (root) {
        done = true;
        return;
      }
      x /= 2;
      y /= 2;
      ++level;
      span *= 2;
    }
    ADD_FAILURE() << "the climb outran its loop bound";
  }
};

struct Walk {
  long long count = 0;  // occluding texels
  int visits = 0;       // nodes the cursor stood on
};

// minmax_pcf_count: the occluder count of a window inside the map.
Walk cursor_walk(const MinMaxMip& mip, const TexelRect& w, float reference) {
  Walk walk;
  Cursor cursor(w);
  while (!cursor.done) {
    ++walk.visits;
    const TexelRect part = intersect(
        {cursor.x * cursor.span, cursor.y * cursor.span, cursor.x * cursor.span + cursor.span - 1,
         cursor.y * cursor.span + cursor.span - 1},
        w);
    bool descend = false;
    if (!part.empty()) {
      // The shader reads only nodes that exist in their level.
      EXPECT_TRUE(cursor.x < mip.width(cursor.level) && cursor.y < mip.height(cursor.level))
          << "read outside level " << cursor.level;
      const MinMax range = mip.node(cursor.level, cursor.x, cursor.y);
      if (range.max < reference) {
        walk.count += part.count();
      } else {
        descend = reference > range.min && cursor.level > 0;
      }
    }
    if (descend) {
      cursor.descend();
    } else {
      cursor.next();
    }
  }
  return walk;
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

TEST(MinmaxCursor, VisitsTheReferenceNodesWithinTheBoundAndCountsExactly) {
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
  int most_visits_at_128 = 0;
  for (int kernel = 1; kernel <= 128; ++kernel) {
    const int bound = minmax_max_visits(kernel);
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
        const float reference = sample % 3 == 0 ? 0.5f : unit(random);
        const Walk walk = cursor_walk(mips[m], window, reference);
        ASSERT_LE(walk.visits, bound)
            << "K " << kernel << " map " << map.width() << "x" << map.height() << " window "
            << window.x0 << "," << window.y0;
        ASSERT_EQ(walk.count, count_occluders_brute_force(map, window, reference))
            << "K " << kernel;
        // The reference's stack walk stands on the same nodes.
        ASSERT_EQ(walk.visits, count_occluders(mips[m], window, reference).visits)
            << "K " << kernel;
        if (kernel == 128) most_visits_at_128 = std::max(most_visits_at_128, walk.visits);
      }
    }
  }
  // The walk does use a good part of the bound: it is not vacuous.
  EXPECT_GT(most_visits_at_128 * 2, minmax_max_visits(128));
}

}  // namespace
}  // namespace penumbra::reference
