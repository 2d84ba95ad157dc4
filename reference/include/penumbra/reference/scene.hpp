// Test scenes in light-view space: rectangular occluders parallel to the
// light plane and solid boxes above a receiver plane, and what a test needs
// from them (the depth pass's triangles, the receivers image, a ray-cast
// shadow map).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "penumbra/model/light.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/support/image.hpp"

namespace penumbra::reference {

// An occluder: x in [x0, x1), y in [y0, y1) at depth z.
struct Rect {
  double x0 = 0.0;
  double y0 = 0.0;
  double x1 = 0.0;
  double y1 = 0.0;
  double z = 0.0;

  bool operator==(const Rect&) const = default;
};

// A solid occluder: x in [x0, x1), y in [y0, y1), z in [z0, z1], its face
// z = z0 toward the light.
struct Box {
  double x0 = 0.0;
  double y0 = 0.0;
  double x1 = 0.0;
  double y1 = 0.0;
  double z0 = 0.0;
  double z1 = 0.0;

  bool operator==(const Box&) const = default;
};

struct Scene {
  std::string name;
  std::vector<Rect> occluders;
  std::vector<Box> boxes;
  // The receiver plane z = plane_z0 + plane_dzdx x + plane_dzdy y.
  double plane_z0 = 16.0;
  double plane_dzdx = 0.0;
  double plane_dzdy = 0.0;
  LightParams light;  // the light and projection the scene is laid out for
  // Default image sizes. The receivers' size differs from the map's so that
  // receivers fall at varied sub-texel positions.
  int map_width = 256;
  int map_height = 256;
  int receivers_width = 200;
  int receivers_height = 168;
  double far_z = 32.0;  // the depth of an empty texel (a cleared map)

  bool operator==(const Scene&) const = default;
};

// The project's scenes; names are unique and stable.
std::vector<Scene> builtin_scenes();

// `scene` laid out for a map in `encoding`: itself, but for an orthographic
// map, whose light becomes directional: the box as wide as the scene's
// frustum at plane_z0 (the receivers' texel density), and ray slopes up to
// L / plane_z0 (the angle its area light spans seen from the plane).
Scene for_map_encoding(Scene scene, MapEncoding encoding);

// The occluders as a triangle list in light-view space, two per rectangle
// and twelve per box (winding unspecified: draw with culling off).
std::vector<std::array<float, 3>> triangles(const Scene& scene);

// A receivers image (3 channels: u, v, z_r): pixel (i, j) at
// u = (i + 0.5) / width, v = (j + 0.5) / height, z_r on the receiver plane.
FloatImage receivers(const Scene& scene, int width, int height);

// What the depth pass should render: the linear z of the nearest occluder on
// the ray through each texel centre, or far_z where there is none. With
// `within` (in texels), the ray through (i + 0.5 + within.x, j + 0.5 +
// within.y) instead: a point near the centre.
FloatImage ray_cast_depth(const Scene& scene, int width, int height, double far_z,
                          std::array<double, 2> within = {0.0, 0.0});

}  // namespace penumbra::reference
