// The built-in scenes. Both use the whitepaper's light (L = 0.5, Fw = 3.75,
// n = 9.5), for which u = 0.5 + x * 2.533 / z: the map spans |x| < 2.07 at
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
// footprints overlap (the nearer one wins in the map), and one that leaves
// the map across a corner.
Scene tilted_overlap() {
  Scene scene;
  scene.name = "tilted_overlap";
  scene.occluders = {
      {-2.0, -1.2, 0.5, 0.3, 11.5},  // u, v ~ [0.06, 0.61] x [0.24, 0.57]
      {-0.5, -0.5, 1.5, 1.5, 13.0},  // u, v ~ [0.40, 0.79]^2, partly behind the first
      {-3.5, 0.8, -1.0, 2.2, 10.5},  // u ~ [-0.34, 0.26], v ~ [0.69, 1.03]: a corner
      {1.0, -2.5, 2.5, -1.0, 15.0},  // u, v ~ [0.67, 0.92] x [0.08, 0.33]
      {-0.6, 1.8, 0.6, 2.3, 14.0},   // a thin bar: u, v ~ [0.39, 0.61] x [0.83, 0.92]
  };
  scene.plane_z0 = 17.0;
  scene.plane_dzdx = 0.12;
  scene.plane_dzdy = 0.08;
  return scene;
}

}  // namespace

std::vector<Scene> builtin_scenes() {
  return {steps(), tilted_overlap()};
}

}  // namespace penumbra::reference
