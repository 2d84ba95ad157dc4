// Each scene isolates one cause of error. With the NVIDIA PCSS whitepaper's
// light and projection (L = 0.5, Fw = 3.75, n = 9.5; the map spans
// |x| < 0.197 z), unless a scene says otherwise.
#include "penumbra/reference/accuracy_scenes.hpp"

namespace penumbra::reference {
namespace {

Scene suite_scene(std::string name) {
  Scene scene;
  scene.name = std::move(name);
  scene.plane_z0 = 16.0;
  scene.map_width = 512;
  scene.map_height = 512;
  scene.receivers_width = 96;
  scene.receivers_height = 96;
  return scene;
}

// Contact hardening: a block standing on the receiver and a slab just above
// it, whose penumbrae shrink to nothing where they touch.
Scene contact() {
  Scene scene = suite_scene("contact");
  scene.light.bias = 0.02;  // the block's foot is at the receiver's depth
  scene.boxes = {{-2.0, -1.2, -0.6, 0.4, 12.5, 16.0}};
  scene.occluders = {{0.3, -0.5, 2.2, 1.6, 15.4}};
  return scene;
}

// Occluders at three depths, each overlapping the next in the light's view:
// one average blocker depth cannot describe them, and back-projection
// counts the overlap twice.
Scene overlap() {
  Scene scene = suite_scene("overlap");
  scene.occluders = {
      {-1.8, -1.4, 0.2, 0.4, 10.5}, {-0.6, -0.6, 1.6, 1.4, 12.5}, {0.4, 0.2, 2.4, 2.2, 14.5}};
  return scene;
}

// Thin features: bars narrower than the blocker search and a pole whose
// shadow is all penumbra.
Scene thin() {
  Scene scene = suite_scene("thin");
  scene.occluders = {
      {-1.8, -1.6, 1.6, -1.5, 11.0}, {-1.6, -0.4, -1.45, 1.8, 12.0}, {0.2, 0.6, 2.0, 0.68, 13.5}};
  scene.boxes = {{0.8, -0.6, 1.0, -0.4, 10.5, 16.0}};
  return scene;
}

// A light three times the whitepaper's: penumbrae wider than most filters'
// sample spacing, and a blocker search that reaches far.
Scene large_light() {
  Scene scene = suite_scene("large_light");
  scene.light.light_world_size = 1.5;
  scene.occluders = {{-1.6, -1.6, -0.2, 0.2, 11.0}, {0.4, -0.4, 2.2, 1.8, 13.5}};
  return scene;
}

// A receiver sloping away from the light (dz/dx = 0.3, bias 0.05): the
// parallel-plane estimate of PCSS assumes a receiver facing the light. (The
// maps hold the occluders only, so no receiver here shadows itself.)
Scene slope() {
  Scene scene = suite_scene("slope");
  scene.light.bias = 0.05;
  scene.plane_dzdx = 0.3;
  scene.occluders = {{-1.2, -1.0, 0.4, 0.6, 11.5}, {0.6, -1.6, 1.8, 1.4, 13.0}};
  return scene;
}

}  // namespace

std::vector<Scene> accuracy_scenes() {
  return {contact(), overlap(), thin(), large_light(), slope()};
}

}  // namespace penumbra::reference
