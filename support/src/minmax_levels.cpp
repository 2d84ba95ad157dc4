#include "penumbra/support/minmax_levels.hpp"

#include <algorithm>

namespace penumbra {

int minmax_top_level(int width, int height) {
  int level = 1;
  while ((1 << level) < std::max(width, height)) ++level;
  return level;
}

std::vector<LevelSize> minmax_level_sizes(int width, int height) {
  std::vector<LevelSize> sizes;
  LevelSize size{width, height};
  for (int level = 1; level <= minmax_top_level(width, height); ++level) {
    size = {(size.width + 1) / 2, (size.height + 1) / 2};
    sizes.push_back(size);
  }
  return sizes;
}

int minmax_chain_side(int width, int height) {
  return 1 << (minmax_top_level(width, height) - 1);
}

std::array<float, 4> size_vec4(int width, int height) {
  const auto w = static_cast<float>(width);
  const auto h = static_cast<float>(height);
  return {w, h, 1.0f / w, 1.0f / h};
}

}  // namespace penumbra
