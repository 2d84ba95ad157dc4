#include "scene_fixture.hpp"

#include <algorithm>
#include <cmath>

#include "penumbra/reference/screen_blur.hpp"
#include "penumbra/verify/shadow_params.hpp"

namespace penumbra {
namespace {

// A texel's centre lies clear of every occluder edge when the rays through
// points kClearance texels from it, along both axes, meet the surface the
// centre's ray meets: every rasterizer then covers it as the ray cast does,
// whatever its pixel-centre rule, once the geometry is placed by it (D3D9's
// half pixel). A map one row off fails on every edge it crosses. Rasterizers
// place edges to 1/2^subTexelPrecisionBits, at least 1/16 texel (Vulkan,
// D3D10+), so 1/8 leaves room.
constexpr double kClearance = 1.0 / 8.0;

bool same_surface(float a, float b) {
  return std::abs(double(a) - b) <= 1e-3 * std::abs(double(a));
}

}  // namespace

DepthCheck check_depth(const reference::Scene& scene, Target target, const FloatImage& gpu,
                       const std::string& backend) {
  const FloatImage expected = reference::ray_cast_depth(scene, gpu.width, gpu.height, scene.far_z);
  std::vector<FloatImage> near;
  for (const std::array<double, 2> within :
       {std::array{kClearance, 0.0}, std::array{-kClearance, 0.0}, std::array{0.0, kClearance},
        std::array{0.0, -kClearance}}) {
    near.push_back(reference::ray_cast_depth(scene, gpu.width, gpu.height, scene.far_z, within));
  }
  DepthCheck check;
  check.scene = scene.name;
  check.target = target;
  check.backend = backend;
  for (int j = 0; j < gpu.height; ++j) {
    for (int i = 0; i < gpu.width; ++i) {
      const float centre = expected.at(i, j);
      if (!std::all_of(near.begin(), near.end(),
                       [&](const FloatImage& n) { return same_surface(centre, n.at(i, j)); })) {
        continue;
      }
      ++check.texels;
      const double error = std::abs(double(gpu.at(i, j)) - centre);
      check.max_abs_error = std::max(check.max_abs_error, error);
      // Interpolated z carries float rounding; 1e-5 relative is ~100 ulps.
      if (!(error <= 1e-5 * centre)) ++check.mismatched;
    }
  }
  check.pass = check.texels > 0 && check.mismatched == 0;
  return check;
}

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
  fixture.depth_check = check_depth(scene, target, fixture.linear_depth, "vulkan");
  return fixture;
}

}  // namespace penumbra
