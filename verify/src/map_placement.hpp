// A scene's map placed as an atlas or array variant reads it: one tile of
// an atlas, or one layer of a 2D array texture (map_layout). What verify
// hands such a variant's passes, so that every read outside the tile or
// layer shows. The reference still reads the map itself: a tile or layer
// read as the variant reads it gives what the map alone gives
// (docs/techniques.md, "Map layouts").
#pragma once

#include "penumbra/model/map_layout.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/vulkan/engine.hpp"
#include "scene_fixture.hpp"

namespace penumbra {

// Texels of the atlas around the map's tile on every side: wider than any
// read a variant makes beyond the map's edge, so each would land on them
// (and beyond them the atlas's own edge clamps to them too).
inline constexpr int kAtlasBorder = 16;

// The array's layers, and the one that holds the map: a read of the wrong
// layer, either side, lands on another.
inline constexpr int kArrayLayers = 3;
inline constexpr int kArrayLayer = 1;

// Where verify's scenes put a map for `layout`: layer kArrayLayer of
// kArrayLayers, or the one tile of an atlas.
MapPlacement scene_placement(MapLayout layout);

// `map` (a map of `fixture`'s scene as stored) placed as `placement` says:
// layer `slot` of `slots`, or tile `slot` of an atlas of `slots` tiles in a
// square grid, row by row, each tile kAtlasBorder texels larger on every
// side than the map. Every other texel holds the nearest depth the
// fixture's encoding stores: an occluder at the near plane, so that a read
// that leaves the tile or layer shadows.
FloatImage place_map(const SceneFixture& fixture, const FloatImage& map,
                     const MapPlacement& placement);

// `fixture` with its map placed (place_map()), uploaded on `engine`;
// ShadowParams name the tile (shadow_map_size the atlas's, map_tile the
// tile's) or the layer (map_layer). The map's own images (normalized_depth,
// linear_depth) stay for the reference. Errors: the upload's.
Result<SceneFixture> placed_fixture(Engine& engine, const SceneFixture& fixture,
                                    const MapPlacement& placement);

// `precision` widened by how far the float32 arithmetic that places a
// receiver's samples in `fixture`'s atlas (shaderlib's map_uv()) may move
// them, in texels; `precision` itself for a fixture with no atlas (a layer
// is read at its own coordinates).
reference::SamplingPrecision placement_precision(const SceneFixture& fixture,
                                                 reference::SamplingPrecision precision);

}  // namespace penumbra
