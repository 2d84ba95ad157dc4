// Exact visibility: seen from a point, each occluder's shadow on the light
// plane is a convex polygon (a rectangle's is an axis-aligned rectangle, a
// box's the hull of its projected corners), so the occluded part of the
// light is the area of a union of convex polygons clipped to the light
// square (convex_union.cpp). A directional light's square is one of ray
// slopes, and a point's shadow there is the slopes whose rays it blocks.
#include "penumbra/reference/exact_visibility.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <vector>

#include "convex_union.hpp"

namespace penumbra::reference {
namespace {

// The point (x', y', z') seen from P = (px, py, pz), z' < pz, lands on z = 0 at
// P + (x' - P) pz / (pz - z').
Point2 project_from(double px, double py, double pz, double x, double y, double z) {
  const double scale = pz / (pz - z);
  return {px + (x - px) * scale, py + (y - py) * scale};
}

// The slope (s_x, s_y) of the directional ray that reaches P = (px, py, pz)
// through (x', y', z'), z' < pz: P - s (pz - z') = (x', y').
Point2 slope_through(double px, double py, double pz, double x, double y, double z) {
  const double scale = 1.0 / (pz - z);
  return {(px - x) * scale, (py - y) * scale};
}

}  // namespace

double exact_visibility(const Scene& scene, double x, double y, double z) {
  const double L = scene.light.light_world_size;
  const auto shadow_of = scene.light.orthographic() ? slope_through : project_from;
  // Only what lies nearer the light than z - bias occludes; a box reaching
  // past that depth is cut there (never at z itself, where the projection
  // has no bound).
  const double limit = z - std::max(scene.light.bias, 1e-9 * z);
  std::vector<ConvexPolygon> shadows;
  const auto add = [&](ConvexPolygon shadow) {
    shadow = clip_to_square(shadow, L);
    if (!shadow.empty()) shadows.push_back(std::move(shadow));
  };
  for (const Rect& r : scene.occluders) {
    if (!(r.z < z - scene.light.bias)) continue;
    add({shadow_of(x, y, z, r.x0, r.y0, r.z), shadow_of(x, y, z, r.x1, r.y0, r.z),
         shadow_of(x, y, z, r.x1, r.y1, r.z), shadow_of(x, y, z, r.x0, r.y1, r.z)});
  }
  for (const Box& b : scene.boxes) {
    if (!(b.z0 < limit)) continue;
    const double z1 = std::min(b.z1, limit);
    std::vector<Point2> corners;
    for (double cz : {b.z0, z1}) {
      for (double cy : {b.y0, b.y1}) {
        for (double cx : {b.x0, b.x1}) corners.push_back(shadow_of(x, y, z, cx, cy, cz));
      }
    }
    add(convex_hull(std::move(corners)));
  }
  return 1.0 - union_area(shadows) / (4 * L * L);
}

Scene clipped_to_map(const Scene& scene) {
  Scene clipped = scene;
  clipped.occluders.clear();
  for (const Rect& r : scene.occluders) {
    const double half = scene.light.orthographic()
                            ? scene.light.frustum_width / 2
                            : scene.light.frustum_width * r.z / (2 * scene.light.near_plane);
    const Rect inside{std::max(r.x0, -half), std::max(r.y0, -half), std::min(r.x1, half),
                      std::min(r.y1, half), r.z};
    if (inside.x0 < inside.x1 && inside.y0 < inside.y1) clipped.occluders.push_back(inside);
  }
  return clipped;
}

FloatImage exact_visibility_image(const Scene& scene, const FloatImage& receivers) {
  FloatImage image(receivers.width, receivers.height, 1);
  // Rows in parallel: every pixel is its own integral, written to its own place.
  tbb::parallel_for(0, receivers.height, [&](int j) {
    for (int i = 0; i < receivers.width; ++i) {
      const double z = receivers.at(i, j, 2);
      const UV xy = map_ray(scene.light, receivers.at(i, j, 0), receivers.at(i, j, 1)).at(z);
      image.at(i, j) = float(exact_visibility(scene, xy.u, xy.v, z));
    }
  });
  return image;
}

}  // namespace penumbra::reference
