#include "map_placement.hpp"

#include <algorithm>

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

}  // namespace

FloatImage place_map(const SceneFixture& fixture, const FloatImage& map, MapLayout layout) {
  if (layout == MapLayout::array) {
    FloatImage array(map.width, map.height * kArrayLayers, 1, nearest_depth(fixture));
    array.layers = kArrayLayers;
    copy_into(array, map, 0, kArrayLayer * map.height);
    return array;
  }
  FloatImage atlas(map.width + 2 * kAtlasBorder, map.height + 2 * kAtlasBorder, 1,
                   nearest_depth(fixture));
  copy_into(atlas, map, kAtlasBorder, kAtlasBorder);
  return atlas;
}

Result<SceneFixture> placed_fixture(Engine& engine, const SceneFixture& fixture, MapLayout layout) {
  const FloatImage& map = fixture.normalized_depth;
  auto placed = std::make_shared<const FloatImage>(place_map(fixture, map, layout));
  SceneFixture out = fixture;
  PENUMBRA_TRY_ASSIGN(out.map, engine.upload_shadow_map(*placed));
  if (layout == MapLayout::array) {
    out.params["map_layer"] = {float(kArrayLayer), 0.0f, 0.0f, 0.0f};
  } else {
    place_in_atlas(out.params, placed->width, placed->height,
                   {kAtlasBorder, kAtlasBorder, map.width, map.height});
  }
  out.placed = std::move(placed);
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
