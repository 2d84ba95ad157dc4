#include "map_placement.hpp"

#include <algorithm>
#include <array>

#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/shadow_params.hpp"

namespace penumbra {
namespace {

// The value that puts an occluder at the near plane: the smallest the
// encoding stores, or reversed-Z's largest.
float nearest_depth(const SceneFixture& fixture) {
  return fixture.encoded && !depth_increases(fixture.encoded->encoding) ? 1.0f : 0.0f;
}

// `map` copied into `out` with its first texel at (x, y).
void copy_into(FloatImage& out, const FloatImage& map, int x, int y) {
  for (int j = 0; j < map.height; ++j) {
    for (int i = 0; i < map.width; ++i) out.at(x + i, y + j) = map.at(i, j);
  }
}

// The columns of a square grid of `slots` tiles.
int grid_columns(int slots) {
  int columns = 1;
  while (columns * columns < slots) ++columns;
  return columns;
}

// The first texel of tile `slot`'s map in the atlas.
std::array<int, 2> tile_origin(const FloatImage& map, const MapPlacement& placement) {
  const int columns = grid_columns(placement.slots);
  return {(placement.slot % columns) * (map.width + 2 * kAtlasBorder) + kAtlasBorder,
          (placement.slot / columns) * (map.height + 2 * kAtlasBorder) + kAtlasBorder};
}

}  // namespace

MapPlacement scene_placement(MapLayout layout) {
  if (layout == MapLayout::array) return {layout, kArrayLayer, kArrayLayers};
  return {layout, 0, 1};
}

FloatImage place_map(const SceneFixture& fixture, const FloatImage& map,
                     const MapPlacement& placement) {
  if (placement.layout == MapLayout::array) {
    FloatImage array(map.width, map.height * placement.slots, 1, nearest_depth(fixture));
    array.layers = placement.slots;
    copy_into(array, map, 0, placement.slot * map.height);
    return array;
  }
  const std::array<int, 2> at = tile_origin(map, placement);
  const int columns = grid_columns(placement.slots);
  const int rows = (placement.slots + columns - 1) / columns;
  FloatImage atlas(columns * (map.width + 2 * kAtlasBorder), rows * (map.height + 2 * kAtlasBorder),
                   1, nearest_depth(fixture));
  copy_into(atlas, map, at[0], at[1]);
  return atlas;
}

Result<SceneFixture> placed_fixture(Engine& engine, const SceneFixture& fixture,
                                    const MapPlacement& placement) {
  const FloatImage& map = fixture.normalized_depth;
  auto placed = std::make_shared<const FloatImage>(place_map(fixture, map, placement));
  SceneFixture out = fixture;
  PENUMBRA_TRY_ASSIGN(out.map, engine.upload_shadow_map(*placed));
  if (placement.layout == MapLayout::array) {
    out.params["map_layer"] = {float(placement.slot), 0.0f, 0.0f, 0.0f};
  } else {
    const std::array<int, 2> at = tile_origin(map, placement);
    place_in_atlas(out.params, placed->width, placed->height,
                   {at[0], at[1], map.width, map.height});
  }
  out.placed = std::move(placed);
  out.placement = placement;
  return out;
}

reference::SamplingPrecision placement_precision(const SceneFixture& fixture,
                                                 reference::SamplingPrecision precision) {
  if (fixture.layout() == MapLayout::atlas) {
    precision.coordinate_error =
        reference::atlas_coordinate_error(fixture.placed->width, fixture.placed->height);
  }
  return precision;
}

}  // namespace penumbra
