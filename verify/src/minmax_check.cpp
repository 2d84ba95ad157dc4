#include "minmax_check.hpp"

#include <bit>
#include <cstdint>

#include "penumbra/reference/minmax_mip.hpp"

namespace penumbra {
namespace {

bool same_bits(float a, float b) {
  return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}

}  // namespace

MinmaxCheck check_minmax(const SceneFixture& fixture, Target target,
                         const std::vector<FloatImage>& levels) {
  const reference::MinMaxMip expected{reference::ShadowMapView(fixture.normalized_depth)};
  MinmaxCheck check;
  check.scene = fixture.scene.name;
  check.target = target;
  check.levels = static_cast<int>(levels.size());
  check.expected_levels = expected.top_level();
  if (check.levels != check.expected_levels) return check;
  for (int l = 1; l <= expected.top_level(); ++l) {
    const FloatImage& gpu = levels[static_cast<std::size_t>(l - 1)];
    if (gpu.width != expected.width(l) || gpu.height != expected.height(l)) {
      ++check.mismatched;
      continue;
    }
    for (int j = 0; j < gpu.height; ++j) {
      for (int i = 0; i < gpu.width; ++i) {
        const reference::MinMax node = expected.node(l, i, j);
        ++check.texels;
        if (!same_bits(gpu.at(i, j, 0), node.min) || !same_bits(gpu.at(i, j, 1), node.max)) {
          ++check.mismatched;
        }
      }
    }
  }
  check.pass = check.texels > 0 && check.mismatched == 0;
  return check;
}

}  // namespace penumbra
