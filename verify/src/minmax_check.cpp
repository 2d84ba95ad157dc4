#include "minmax_check.hpp"

#include <bit>
#include <cmath>
#include <cstdint>

#include "penumbra/reference/minmax_mip.hpp"

namespace penumbra {
namespace {

bool same_bits(float a, float b) {
  return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}

// How far an encoded map's node may lie from the exact decoding, relative:
// minmax_init decodes each texel in float32 (a division, products and
// sums of operands near 1: well within 2^-19) and min and max keep the
// error of the texel they pick.
constexpr double kDecodedTolerance = 0x1p-19;

}  // namespace

MinmaxCheck check_minmax(const SceneFixture& fixture, Target target,
                         const std::vector<FloatImage>& levels) {
  // An encoded map's mip holds the shader's decoding, z * depth_scale; a
  // linear map's the stored values themselves.
  const bool decoded = fixture.encoded.has_value();
  const reference::MinMaxMip expected{
      reference::ShadowMapView(decoded ? fixture.linear_depth : fixture.normalized_depth)};
  const double scale = depth_scale_for(fixture.scene.far_z);
  const auto agrees = [&](float gpu, float node) {
    if (!decoded) return same_bits(gpu, node);
    const double want = double(node) * scale;
    return std::abs(double(gpu) - want) <= kDecodedTolerance * std::abs(want);
  };
  MinmaxCheck check;
  check.scene = fixture.scene.name;
  check.target = target;
  if (fixture.encoded) check.map_encoding = fixture.encoded->encoding;
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
        if (!agrees(gpu.at(i, j, 0), node.min) || !agrees(gpu.at(i, j, 1), node.max)) {
          ++check.mismatched;
        }
      }
    }
  }
  check.pass = check.texels > 0 && check.mismatched == 0;
  return check;
}

}  // namespace penumbra
