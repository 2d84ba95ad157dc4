#include "scene_fixture.hpp"

#include <algorithm>
#include <cmath>

#include "penumbra/reference/screen_blur.hpp"
#include "penumbra/verify/shadow_params.hpp"

namespace penumbra {
namespace {

// Texels whose 3x3 neighbourhood in the ray cast is uniform: away from
// occluder edges, where rasterization rules decide coverage.
bool interior(const FloatImage& ray_cast, int i, int j) {
  const float centre = ray_cast.at(i, j);
  for (int dj = -1; dj <= 1; ++dj) {
    for (int di = -1; di <= 1; ++di) {
      const int x = std::clamp(i + di, 0, ray_cast.width - 1);
      const int y = std::clamp(j + dj, 0, ray_cast.height - 1);
      if (ray_cast.at(x, y) != centre) return false;
    }
  }
  return true;
}

DepthCheck check_depth(const reference::Scene& scene, Target target, const FloatImage& gpu) {
  const FloatImage expected = reference::ray_cast_depth(scene, gpu.width, gpu.height, scene.far_z);
  DepthCheck check;
  check.scene = scene.name;
  check.target = target;
  for (int j = 0; j < gpu.height; ++j) {
    for (int i = 0; i < gpu.width; ++i) {
      if (!interior(expected, i, j)) continue;
      ++check.texels;
      const double error = std::abs(double(gpu.at(i, j)) - expected.at(i, j));
      check.max_abs_error = std::max(check.max_abs_error, error);
      // Interpolated z carries float rounding; 1e-5 relative is ~100 ulps.
      if (!(error <= 1e-5 * expected.at(i, j))) ++check.mismatched;
    }
  }
  check.pass = check.texels > 0 && check.mismatched == 0;
  return check;
}

}  // namespace

Result<SceneFixture> prepare_scene(Engine& engine, const PassProgram& depth, Target target,
                                   const reference::Scene& scene, FloatImage receivers) {
  SceneFixture fixture;
  fixture.scene = scene;
  const float depth_scale = depth_scale_for(scene.far_z);
  fixture.params = shadow_params(
      scene.light,
      {scene.map_width, scene.map_height, scene.receivers_width, scene.receivers_height},
      depth_scale);
  const auto triangles = reference::triangles(scene);
  auto map =
      engine.render_depth(depth, triangles, scene.map_width, scene.map_height, fixture.params);
  if (!map) return map.error();
  fixture.map = *map;
  auto normalized = engine.read_shadow_map(**map);
  if (!normalized) return normalized.error();
  fixture.normalized_depth = *normalized;
  fixture.linear_depth = std::move(*normalized);
  for (float& d : fixture.linear_depth.data) d /= depth_scale;  // exact: a power of two
  fixture.receivers = std::move(receivers);
  fixture.colour = reference::scene_colour(scene.receivers_width, scene.receivers_height);
  fixture.depth_check = check_depth(scene, target, fixture.linear_depth);
  return fixture;
}

}  // namespace penumbra
