// Geometry of the test scenes: every occluder and the receiver plane are met
// by rays from the light's centre through texel or pixel centres.
#include <algorithm>

#include "penumbra/reference/scene.hpp"

namespace penumbra::reference {

std::vector<std::array<float, 3>> triangles(const Scene& scene) {
  std::vector<std::array<float, 3>> vertices;
  vertices.reserve(6 * scene.occluders.size());
  for (const Rect& r : scene.occluders) {
    const float x0 = float(r.x0), y0 = float(r.y0), x1 = float(r.x1), y1 = float(r.y1);
    const float z = float(r.z);
    vertices.insert(vertices.end(),
                    {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y0, z}, {x1, y1, z}, {x0, y1, z}});
  }
  return vertices;
}

FloatImage receivers(const Scene& scene, int width, int height) {
  FloatImage image(width, height, 3);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const double u = (i + 0.5) / width;
      const double v = (j + 0.5) / height;
      // The ray (s_x z, s_y z, z) meets z = z0 + a x + b y at z0 / (1 - a s_x - b s_y).
      const UV slope = ray_slope(scene.light, u, v);
      const double z =
          scene.plane_z0 / (1.0 - scene.plane_dzdx * slope.u - scene.plane_dzdy * slope.v);
      image.at(i, j, 0) = float(u);
      image.at(i, j, 1) = float(v);
      image.at(i, j, 2) = float(z);
    }
  }
  return image;
}

FloatImage ray_cast_depth(const Scene& scene, int width, int height, double far_z) {
  FloatImage image(width, height, 1);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const UV slope = ray_slope(scene.light, (i + 0.5) / width, (j + 0.5) / height);
      double nearest = far_z;
      for (const Rect& r : scene.occluders) {
        const double x = slope.u * r.z;
        const double y = slope.v * r.z;
        if (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1) nearest = std::min(nearest, r.z);
      }
      image.at(i, j) = float(nearest);
    }
  }
  return image;
}

}  // namespace penumbra::reference
