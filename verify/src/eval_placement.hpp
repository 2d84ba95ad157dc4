// Where `penumbra eval`'s light lies in the map it is given: the whole map,
// one tile of an atlas (--map-tile, map_layout atlas) or one layer of an
// array stacked in it (--map-layer, map_layout array).
#pragma once

#include "penumbra/library/library.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/support/param_block.hpp"
#include "penumbra/verify/eval.hpp"

namespace penumbra {

// The tile inside the map, at least one texel each way; the layer one of
// the count, which divides the map's height. Errors name the argument.
Status check_placement(const EvalInputs& inputs);

// A tile is for an atlas variant and a layer for an array variant: errors
// name the argument and the variant.
Status check_placement_variant(const LibraryVariant& variant, const EvalInputs& inputs);

// The light's own map in `map` (the given map, stored or linear): its tile,
// its layer, or the whole map.
FloatImage light_map(const FloatImage& map, const EvalInputs& inputs);

// `stored` as the device uploads it for `variant`: an array variant's as
// the layers of an array (the given count, or one), else as it is.
FloatImage device_map(FloatImage stored, const LibraryVariant& variant, const EvalInputs& inputs);

// The parameters of `inputs`' light for the device: its map's size (a
// tile's or a layer's, which the filter radius's default is in texels of)
// and, for an atlas, the atlas's size and the tile in texture coordinates;
// for an array, the layer.
ParamBlock device_params(const EvalInputs& inputs, const FloatImage& receivers, float depth_scale);

// The reference's precision for the light's placement: on a tile's texels,
// its placement in the atlas rounded as the shaders round it.
reference::SamplingPrecision placement_precision(const EvalInputs& inputs);

}  // namespace penumbra
