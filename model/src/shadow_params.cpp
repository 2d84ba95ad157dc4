#include "penumbra/model/shadow_params.hpp"

#include <array>
#include <cmath>

#include "penumbra/support/minmax_levels.hpp"

namespace penumbra {

float depth_scale_for(double max_z) {
  const int exponent = max_z > 1.0 ? static_cast<int>(std::ceil(std::log2(max_z))) : 0;
  return std::ldexp(1.0f, -exponent);
}

ParamBlock shadow_params(const LightParams& light, const ParamSizes& sizes, float depth_scale) {
  const auto f = [](double value) { return static_cast<float>(value); };
  const std::array<float, 4> map_size = size_vec4(sizes.map_width, sizes.map_height);
  return {
      {"shadow_map_size", map_size},
      {"light",
       {f(light.light_world_size), f(light.frustum_width), f(light.near_plane),
        f(light.light_size_uv())}},
      {"sampling",
       {f(light.filter_radius(sizes.map_width)), f(light.bias), depth_scale, 1.0f / depth_scale}},
      {"screen_size", size_vec4(sizes.screen_width, sizes.screen_height)},
      // The min-max build passes set source_size per level (Engine::build_minmax).
      {"source_size", map_size},
      {"minmax_info",
       {static_cast<float>(minmax_top_level(sizes.map_width, sizes.map_height)), 0.0f, 0.0f, 0.0f}},
      // An atlas variant's tile: the whole texture, where the map fills it.
      {"map_tile", {0.0f, 0.0f, 1.0f, 1.0f}},
      // An array variant's layer: the first.
      {"map_layer", {0.0f, 0.0f, 0.0f, 0.0f}},
  };
}

void place_in_atlas(ParamBlock& params, int atlas_width, int atlas_height,
                    const std::array<int, 4>& tile) {
  const auto w = double(atlas_width), h = double(atlas_height);
  params["shadow_map_size"] = size_vec4(atlas_width, atlas_height);
  params["map_tile"] = {float(tile[0] / w), float(tile[1] / h), float(tile[2] / w),
                        float(tile[3] / h)};
}

}  // namespace penumbra
