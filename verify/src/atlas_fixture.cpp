#include "atlas_fixture.hpp"

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

}  // namespace

FloatImage atlas_around(const SceneFixture& fixture, const FloatImage& map) {
  FloatImage atlas(map.width + 2 * kAtlasBorder, map.height + 2 * kAtlasBorder, 1);
  std::ranges::fill(atlas.data, nearest_depth(fixture));
  for (int j = 0; j < map.height; ++j) {
    for (int i = 0; i < map.width; ++i) {
      atlas.at(kAtlasBorder + i, kAtlasBorder + j) = map.at(i, j);
    }
  }
  return atlas;
}

Result<SceneFixture> atlas_fixture(Engine& engine, const SceneFixture& fixture) {
  const FloatImage& map = fixture.normalized_depth;
  auto atlas = std::make_shared<const FloatImage>(atlas_around(fixture, map));
  SceneFixture out = fixture;
  PENUMBRA_TRY_ASSIGN(out.map, engine.upload_shadow_map(*atlas));
  place_in_atlas(out.params, atlas->width, atlas->height,
                 {kAtlasBorder, kAtlasBorder, map.width, map.height});
  out.atlas = std::move(atlas);
  return out;
}

reference::SamplingPrecision atlas_precision(const SceneFixture& fixture,
                                             reference::SamplingPrecision precision) {
  if (fixture.atlas) {
    precision.coordinate_error =
        reference::atlas_coordinate_error(fixture.atlas->width, fixture.atlas->height);
  }
  return precision;
}

}  // namespace penumbra
