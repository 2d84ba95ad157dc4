#include "minmax_test_maps.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

#include "default_library.hpp"
#include "penumbra/model/shadow_params.hpp"
#include "penumbra/reference/scene.hpp"

namespace penumbra::testing {

FloatImage hashed_map(int width, int height) {
  FloatImage map(width, height, 1);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      std::uint32_t h =
          static_cast<std::uint32_t>(i) * 0x9E3779B1u ^ static_cast<std::uint32_t>(j) * 0x85EBCA77u;
      h ^= h >> 15;
      h *= 0x2C1B3C6Du;
      h ^= h >> 12;
      map.at(i, j) = static_cast<float>(h & 0xFFFFFFu) / 16777216.0f;  // 24 bits: exact
    }
  }
  return map;
}

std::array<float, 2> brute_force_node(const FloatImage& map, int level, int i, int j) {
  const int span = 1 << level;
  std::array<float, 2> range{2.0f, -1.0f};
  for (int y = j * span; y < std::min((j + 1) * span, map.height); ++y) {
    for (int x = i * span; x < std::min((i + 1) * span, map.width); ++x) {
      range[0] = std::min(range[0], map.at(x, y));
      range[1] = std::max(range[1], map.at(x, y));
    }
  }
  return range;
}

ParamBlock bare_map_params(const FloatImage& map, int receivers_width, int receivers_height) {
  return shadow_params(reference::builtin_scenes().front().light,
                       {map.width, map.height, receivers_width, receivers_height}, 1.0f);
}

MinmaxText default_minmax_passes(Target target) {
  const Variant* variant = find_default_variant("minmax_pcf_k8");
  if (!variant) {
    ADD_FAILURE() << "permutations/default.json has no variant minmax_pcf_k8";
    return {};
  }
  auto text = emitted_minmax(*variant, target);
  if (!text) {
    ADD_FAILURE() << text.error().to_string();
    return {};
  }
  return std::move(*text);
}

}  // namespace penumbra::testing
