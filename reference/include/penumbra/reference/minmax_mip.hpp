// The min-max depth mip of Dmitriev 2007 (docs/verification.md, "Min-max mip"):
// level 0 is the map, level l holds the (min, max) of the map texels
// [i 2^l, (i+1) 2^l) x [j 2^l, (j+1) 2^l) clipped to the map, up to the 1x1
// level N. Also the hierarchical count of occluding texels the minmax_pcf
// shaders perform, node for node.
#pragma once

#include <algorithm>
#include <limits>
#include <vector>

#include "penumbra/reference/shadow_map.hpp"

namespace penumbra::reference {

// Texels x0..x1, y0..y1 (inclusive); empty when x0 > x1 or y0 > y1.
struct TexelRect {
  int x0 = 0;
  int y0 = 0;
  int x1 = -1;
  int y1 = -1;

  bool empty() const { return x0 > x1 || y0 > y1; }
  long long count() const {
    return empty() ? 0 : static_cast<long long>(x1 - x0 + 1) * (y1 - y0 + 1);
  }
};

// The part of `rect` inside a width x height map.
inline TexelRect clip(const TexelRect& rect, int width, int height) {
  return {std::max(rect.x0, 0), std::max(rect.y0, 0), std::min(rect.x1, width - 1),
          std::min(rect.y1, height - 1)};
}

// The common part of two rectangles.
inline TexelRect intersect(const TexelRect& a, const TexelRect& b) {
  return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

// A node's values, linear z as float (the GPU stores z * depth_scale, a
// power of two, so comparisons agree exactly).
struct MinMax {
  float min = 0.0f;
  float max = 0.0f;
};

class MinMaxMip {
 public:
  explicit MinMaxMip(const ShadowMapView& map);

  // N = max(1, ceil(log2(max(W, H)))): the index of the 1x1 level.
  int top_level() const { return int(levels_.size()) - 1; }
  // W_0 = W, W_l = ceil(W_{l-1} / 2); the same for heights.
  int width(int level) const { return levels_[level].width; }
  int height(int level) const { return levels_[level].height; }
  // Node (i, j) of `level` (0 <= level <= top_level(), inside that level).
  MinMax node(int level, int i, int j) const {
    const Level& l = levels_[level];
    return l.nodes[std::size_t(j) * l.width + i];
  }
  // The map texels node (i, j) of `level` covers, clipped to the map.
  TexelRect extent(int level, int i, int j) const;

 private:
  struct Level {
    int width = 0;
    int height = 0;
    std::vector<MinMax> nodes;  // row j = 0 first
  };
  std::vector<Level> levels_;
};

// The traversal's start level for a non-empty window inside the map: the
// smallest l with floor(x1 / 2^l) - floor(x0 / 2^l) <= 1, likewise in y, so
// that the window meets at most 2 x 2 nodes of that level.
int start_level(const TexelRect& window);

// The smallest l at which a non-empty window inside the map meets at most
// `nodes` nodes per axis (start_level() is level_spanning(window, 2)).
int level_spanning(const TexelRect& window, int nodes);

struct MipCount {
  long long count = 0;     // occluding texels (depth < z_ref) in the window, inside the map
  int visits = 0;          // nodes the walk stood on, skipped ones included
  int reads = 0;           // nodes whose (min, max) was read: what the shader's .y counts
  int steps = 0;           // steps of the walk: visits and rises (MinmaxCursor)
  bool truncated = false;  // stopped at max_steps before the walk was done
};

// minmax_pcf's traversal (docs/techniques.md), the shaders' MinmaxCursor
// walk: from the 2 x 2 roots of start_level(), depth first with children
// (2i, 2j), (2i+1, 2j), (2i, 2j+1), (2i+1, 2j+1); a node missing the window
// is skipped unread, a node with z_ref <= min adds nothing, one with
// max < z_ref adds its texels in the window, any other is descended.
// `window` may reach outside the map. After `max_steps` steps (a target's
// cap, minmax_max_steps() or more for none) the count is what was reached.
MipCount count_occluders(const MinMaxMip& mip, const TexelRect& window, float z_ref,
                         int max_steps = std::numeric_limits<int>::max());

}  // namespace penumbra::reference
