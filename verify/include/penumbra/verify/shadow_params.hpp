// The ShadowParams block for a light and the map and screen sizes: what
// verify's scenes, `penumbra eval`, the benchmarks and the engines' tests
// hand to every pass (docs/shader-interface.md).
#pragma once

#include <optional>

#include "penumbra/reference/light.hpp"
#include "penumbra/reference/shadow_map.hpp"
#include "penumbra/support/param_block.hpp"

namespace penumbra {

// The power of two 2^-k with 2^k >= max_z, so normalized depth z * scale lies
// in [0, 1] and scaling is exact (docs/shader-interface.md).
float depth_scale_for(double max_z);

// How a map in `encoding` stores depth under the projection these
// parameters describe: `light`'s near plane, and 1 / depth_scale for the far
// one (docs/shader-interface.md); none for linear z.
std::optional<reference::EncodedDepth> encoded_depth(MapEncoding encoding,
                                                     const reference::LightParams& light,
                                                     float depth_scale);

struct ParamSizes {
  int map_width = 0;
  int map_height = 0;
  int screen_width = 0;
  int screen_height = 0;
};

// ShadowParams for `light`, the map and screen sizes, and a depth scale:
// every member, source_size the map's size and minmax_info.x the map's
// min-max top level (minmax_top_level).
ParamBlock shadow_params(const reference::LightParams& light, const ParamSizes& sizes,
                         float depth_scale);

}  // namespace penumbra
