// The built-in scenes. The first two use the NVIDIA PCSS whitepaper's light (L = 0.5,
// Fw = 3.75, n = 9.5), for which u = 0.5 + x * 2.533 / z: the map spans |x| < 2.07 at
// z = 10.5 and |x| < 3.4 at z = 17. Occluders sit at several heights so that
// penumbrae of several widths appear, and each scene has an occluder that
// leaves the map, whose shadow then depends on clamp-to-edge reads.
#include "penumbra/reference/scene.hpp"

namespace penumbra::reference {
namespace {

// Flat receiver at z = 16, four separate occluders from near the light
// (wide penumbra) to near the receiver (narrow one).
Scene steps() {
  Scene scene;
  scene.name = "steps";
  scene.occluders = {
      {-1.6, -1.6, -0.6, -0.4, 10.5},  // u, v ~ [0.11, 0.36] x [0.11, 0.40]
      {0.2, -1.8, 1.4, -0.6, 11.5},    // u, v ~ [0.54, 0.81] x [0.10, 0.37]
      {-1.8, 0.4, -0.4, 1.8, 13.0},    // u, v ~ [0.15, 0.42] x [0.58, 0.85]
      {0.6, 0.5, 3.5, 1.6, 15.0},      // u ~ [0.60, 1.09]: crosses the right edge
  };
  scene.plane_z0 = 16.0;
  return scene;
}

// A receiver tilted in x and y (z ~ 16.3 to 17.8), two occluders whose
// footprints overlap (the nearer one wins in the map), one that leaves the
// map across a corner, and one that crosses the receiver. Its map is
// neither square nor a power of two, so the min-max mip's partial nodes at
// the right and top edges are exercised.
Scene tilted_overlap() {
  Scene scene;
  scene.name = "tilted_overlap";
  scene.occluders = {
      {-2.0, -1.2, 0.5, 0.3, 11.5},  // u, v ~ [0.06, 0.61] x [0.24, 0.57]
      {-0.5, -0.5, 1.5, 1.5, 13.0},  // u, v ~ [0.40, 0.79]^2, partly behind the first
      {-3.5, 0.8, -1.0, 2.2, 10.5},  // u ~ [-0.34, 0.26], v ~ [0.69, 1.03]: a corner
      {1.0, -2.5, 2.5, -1.0, 15.0},  // u, v ~ [0.67, 0.92] x [0.08, 0.33]
      {-0.6, 1.8, 0.6, 2.3, 14.0},   // a thin bar: u, v ~ [0.39, 0.61] x [0.83, 0.92]
      // Crossing the receiver (z = 17 + 0.12 x + 0.08 y) along x ~ 2.2 to
      // 2.6: near the crossing only a receiver-plane depth bias tells the
      // filter's samples in front of the receiver from those behind it.
      {2.0, 0.4, 2.8, 1.0, 17.34},  // u, v ~ [0.79, 0.91] x [0.56, 0.62]
  };
  scene.plane_z0 = 17.0;
  scene.plane_dzdx = 0.12;
  scene.plane_dzdy = 0.08;
  scene.map_width = 250;
  scene.map_height = 190;
  return scene;
}

// Every light parameter away from its default, so a shader that ignores one
// fails: a wider light nearer the map (L = 1, Fw = 4, n = 6: u = 0.5 + 1.5 x / z),
// a pcf_poisson radius of 3 texels, and a bias of 0.05 with a decal 0.01 above
// the receiver, which only the bias keeps from shadowing it.
Scene custom_light() {
  Scene scene;
  scene.name = "custom_light";
  scene.light.light_world_size = 1.0;
  scene.light.frustum_width = 4.0;
  scene.light.near_plane = 6.0;
  scene.light.bias = 0.05;
  scene.light.filter_radius_uv = 3.0 / 256.0;
  scene.occluders = {
      {-2.0, -2.0, -0.5, -0.5, 7.5},  // u, v ~ [0.10, 0.40]
      {0.5, -2.5, 2.5, -0.7, 9.0},    // u, v ~ [0.58, 0.92] x [0.08, 0.38]
      {-3.0, 0.5, -0.5, 2.5, 11.0},   // u, v ~ [0.09, 0.43] x [0.57, 0.84]
      {1.0, 1.0, 5.0, 2.5, 12.5},     // u ~ [0.62, 1.10]: crosses the right edge
      {-0.6, -0.6, 0.6, 0.6, 13.99},  // the decal: within the bias of the receiver
  };
  scene.plane_z0 = 14.0;
  return scene;
}

}  // namespace

std::vector<Scene> builtin_scenes() {
  return {steps(), tilted_overlap(), custom_light()};
}

Scene for_map_encoding(Scene scene, MapEncoding encoding) {
  if (!is_orthographic(encoding) || scene.light.orthographic()) return scene;
  LightParams& light = scene.light;
  light.frustum_width *= scene.plane_z0 / light.near_plane;
  light.light_world_size /= scene.plane_z0;
  light.projection = LightProjection::orthographic;
  return scene;
}

}  // namespace penumbra::reference
