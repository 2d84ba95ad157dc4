// Geometry of the test scenes: every occluder and the receiver plane are met
// by the map's rays (map_ray()) through texel or pixel centres.
#include <tbb/parallel_for.h>

#include <algorithm>

#include "penumbra/reference/scene.hpp"
#include "ray_box.hpp"

namespace penumbra::reference {

std::vector<std::array<float, 3>> triangles(const Scene& scene) {
  std::vector<std::array<float, 3>> vertices;
  vertices.reserve(6 * scene.occluders.size() + 36 * scene.boxes.size());
  for (const Rect& r : scene.occluders) {
    const float x0 = float(r.x0), y0 = float(r.y0), x1 = float(r.x1), y1 = float(r.y1);
    const float z = float(r.z);
    vertices.insert(vertices.end(),
                    {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y0, z}, {x1, y1, z}, {x0, y1, z}});
  }
  for (const Box& b : scene.boxes) {
    // Corner k has x1 when bit 0 is set, y1 for bit 1, z1 for bit 2.
    std::array<std::array<float, 3>, 8> c;
    for (int k = 0; k < 8; ++k) {
      c[k] = {float(k & 1 ? b.x1 : b.x0), float(k & 2 ? b.y1 : b.y0), float(k & 4 ? b.z1 : b.z0)};
    }
    // Each face as its four corners in order around it, two triangles.
    constexpr int kFaces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                  {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    for (const auto& f : kFaces) {
      vertices.insert(vertices.end(), {c[f[0]], c[f[1]], c[f[2]], c[f[0]], c[f[2]], c[f[3]]});
    }
  }
  return vertices;
}

FloatImage receivers(const Scene& scene, int width, int height) {
  FloatImage image(width, height, 3);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const double u = (i + 0.5) / width;
      const double v = (j + 0.5) / height;
      // The ray (o_x + s_x z, o_y + s_y z, z) meets z = z0 + a x + b y at
      // (z0 + a o_x + b o_y) / (1 - a s_x - b s_y).
      const MapRay ray = map_ray(scene.light, u, v);
      const double z =
          (scene.plane_z0 + scene.plane_dzdx * ray.origin.u + scene.plane_dzdy * ray.origin.v) /
          (1.0 - scene.plane_dzdx * ray.slope.u - scene.plane_dzdy * ray.slope.v);
      image.at(i, j, 0) = float(u);
      image.at(i, j, 1) = float(v);
      image.at(i, j, 2) = float(z);
    }
  }
  return image;
}

FloatImage ray_cast_depth(const Scene& scene, int width, int height, double far_z,
                          std::array<double, 2> within) {
  FloatImage image(width, height, 1);
  // Rows in parallel: each texel's ray is its own.
  tbb::parallel_for(0, height, [&](int j) {
    for (int i = 0; i < width; ++i) {
      const MapRay ray =
          map_ray(scene.light, (i + 0.5 + within[0]) / width, (j + 0.5 + within[1]) / height);
      double nearest = far_z;
      for (const Rect& r : scene.occluders) {
        const UV p = ray.at(r.z);
        if (p.u >= r.x0 && p.u < r.x1 && p.v >= r.y0 && p.v < r.y1)
          nearest = std::min(nearest, r.z);
      }
      for (const Box& b : scene.boxes) {
        // With direction (s_u, s_v, 1) from z = 0, the parameter t is the hit's z.
        const auto hit =
            ray_box(b, {ray.origin.u, ray.origin.v, 0.0}, {ray.slope.u, ray.slope.v, 1.0});
        if (hit) nearest = std::min(nearest, hit->t);
      }
      image.at(i, j) = float(nearest);
    }
  });
  return image;
}

}  // namespace penumbra::reference
