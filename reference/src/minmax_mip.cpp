// Building the min-max mip level by level, as the GPU's minmax_init and
// minmax_reduce passes do: each node reduces the 2 x 2 nodes below it, and a
// child past the last node of its level is simply absent (the GPU reads the
// last one again through clamp-to-edge, which changes neither min nor max).
// The level sizes are support's minmax_level_sizes(), as every engine's.
// Since W_l = ceil(W_{l-1} / 2), node (l, i, j) then covers exactly the map
// texels [i 2^l, (i+1) 2^l) x [j 2^l, (j+1) 2^l) clipped to the map.
#include "penumbra/reference/minmax_mip.hpp"

#include <utility>

#include "penumbra/support/minmax_levels.hpp"

namespace penumbra::reference {

MinMaxMip::MinMaxMip(const ShadowMapView& map) {
  Level base{map.width(), map.height(), {}};
  base.nodes.reserve(std::size_t(base.width) * base.height);
  for (int j = 0; j < base.height; ++j) {
    const double* depths = map.row(j);
    for (int i = 0; i < base.width; ++i) {
      const float depth = float(depths[i]);
      base.nodes.push_back({depth, depth});
    }
  }
  levels_.push_back(std::move(base));
  for (const LevelSize& size : minmax_level_sizes(map.width(), map.height())) {
    const Level& below = levels_.back();
    Level next{size.width, size.height, {}};
    next.nodes.reserve(std::size_t(next.width) * next.height);
    for (int j = 0; j < next.height; ++j) {
      for (int i = 0; i < next.width; ++i) {
        MinMax node = below.nodes[std::size_t(2 * j) * below.width + 2 * i];
        for (int dj = 0; dj <= 1; ++dj) {
          for (int di = 0; di <= 1; ++di) {
            const int ci = 2 * i + di, cj = 2 * j + dj;
            if (ci >= below.width || cj >= below.height) continue;
            const MinMax child = below.nodes[std::size_t(cj) * below.width + ci];
            node.min = std::min(node.min, child.min);
            node.max = std::max(node.max, child.max);
          }
        }
        next.nodes.push_back(node);
      }
    }
    levels_.push_back(std::move(next));
  }
}

TexelRect MinMaxMip::extent(int level, int i, int j) const {
  const TexelRect block{i << level, j << level, ((i + 1) << level) - 1, ((j + 1) << level) - 1};
  return clip(block, width(0), height(0));
}

int level_spanning(const TexelRect& window, int nodes) {
  int level = 0;
  while ((window.x1 >> level) - (window.x0 >> level) >= nodes ||
         (window.y1 >> level) - (window.y0 >> level) >= nodes) {
    ++level;
  }
  return level;
}

int start_level(const TexelRect& window) {
  return level_spanning(window, 2);
}

}  // namespace penumbra::reference
