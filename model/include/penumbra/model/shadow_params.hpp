// The ShadowParams block for a light and the map and screen sizes: what an
// engine hands to every pass (docs/shader-interface.md), and what verify's
// scenes, `penumbra eval`, the benchmarks and the runtime's tests hand to
// theirs.
#pragma once

#include <array>

#include "penumbra/model/light.hpp"
#include "penumbra/support/param_block.hpp"

namespace penumbra {

// The power of two 2^-k with 2^k >= max_z, so normalized depth z * scale lies
// in [0, 1] and scaling is exact (docs/shader-interface.md).
float depth_scale_for(double max_z);

struct ParamSizes {
  int map_width = 0;
  int map_height = 0;
  int screen_width = 0;
  int screen_height = 0;
};

// ShadowParams for `light`, the map and screen sizes, and a depth scale:
// every member, source_size the map's size and minmax_info.x the map's
// min-max top level (minmax_top_level).
ParamBlock shadow_params(const LightParams& light, const ParamSizes& sizes, float depth_scale);

// `params` of a light whose map is the tile (x, y, width, height in texels,
// row 0 first) of an `atlas_width` x `atlas_height` atlas (map_layout
// atlas): shadow_map_size becomes the atlas's, map_tile the tile in texture
// coordinates.
void place_in_atlas(ParamBlock& params, int atlas_width, int atlas_height,
                    const std::array<int, 4>& tile);

}  // namespace penumbra
