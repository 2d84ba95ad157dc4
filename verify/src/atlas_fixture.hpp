// A scene's map as one tile of an atlas (map_layout atlas): what verify
// hands an atlas variant's passes, so that every read outside the tile
// shows. The reference still reads the map itself: a tile read as the
// variant reads it gives what the map alone gives (docs/techniques.md,
// "Map layouts").
#pragma once

#include "penumbra/reference/precision.hpp"
#include "penumbra/vulkan/engine.hpp"
#include "scene_fixture.hpp"

namespace penumbra {

// Texels of the atlas around the map's tile on every side: wider than any
// read a variant makes beyond the map's edge, so each would land on them
// (and beyond them the atlas's own edge clamps to them too).
inline constexpr int kAtlasBorder = 16;

// `map` (a map of `fixture`'s scene as stored) as the tile of an atlas
// kAtlasBorder texels larger on every side, whose other texels hold the
// nearest depth the fixture's encoding stores: an occluder at the near
// plane, so that a read that leaves the tile shadows.
FloatImage atlas_around(const SceneFixture& fixture, const FloatImage& map);

// `fixture` with its map moved into atlas_around()'s tile, uploaded on
// `engine`; ShadowParams' shadow_map_size is the atlas's and map_tile the
// tile's. The map's own images (normalized_depth, linear_depth) stay for
// the reference. Errors: the upload's.
Result<SceneFixture> atlas_fixture(Engine& engine, const SceneFixture& fixture);

// `precision` widened by how far the float32 arithmetic that places a
// receiver's samples in `fixture`'s atlas (shaderlib's map_uv()) may move
// them, in texels; `precision` itself for a fixture with no atlas.
reference::SamplingPrecision atlas_precision(const SceneFixture& fixture,
                                             reference::SamplingPrecision precision);

}  // namespace penumbra
