// Exact visibility: every occluder is an axis-aligned rectangle parallel to
// the light, so its shadow volume seen from a point projects onto the light
// plane as an axis-aligned rectangle. The area of a union of such rectangles
// is exact by coordinate compression: the rectangles' edges cut the plane into
// cells, each wholly inside or outside every rectangle.
#include "penumbra/reference/exact_visibility.hpp"

#include <algorithm>
#include <vector>

namespace penumbra::reference {
namespace {

struct Box {
  double x0, y0, x1, y1;
};

double union_area(const std::vector<Box>& boxes) {
  std::vector<double> xs, ys;
  for (const Box& b : boxes) {
    xs.insert(xs.end(), {b.x0, b.x1});
    ys.insert(ys.end(), {b.y0, b.y1});
  }
  std::sort(xs.begin(), xs.end());
  std::sort(ys.begin(), ys.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  double area = 0.0;
  for (std::size_t a = 0; a + 1 < xs.size(); ++a) {
    for (std::size_t b = 0; b + 1 < ys.size(); ++b) {
      const double cx = (xs[a] + xs[a + 1]) / 2, cy = (ys[b] + ys[b + 1]) / 2;
      const bool covered = std::any_of(boxes.begin(), boxes.end(), [&](const Box& box) {
        return box.x0 < cx && cx < box.x1 && box.y0 < cy && cy < box.y1;
      });
      if (covered) area += (xs[a + 1] - xs[a]) * (ys[b + 1] - ys[b]);
    }
  }
  return area;
}

}  // namespace

double exact_visibility(const Scene& scene, double x, double y, double z) {
  const double L = scene.light.light_world_size;
  std::vector<Box> shadows;
  for (const Rect& r : scene.occluders) {
    if (!(r.z < z - scene.light.bias)) continue;
    // From P, the point (x', y', r.z) projects to P + (x' - P) z / (z - r.z) on z = 0.
    const double scale = z / (z - r.z);
    const Box projected{x + (r.x0 - x) * scale, y + (r.y0 - y) * scale, x + (r.x1 - x) * scale,
                        y + (r.y1 - y) * scale};
    const Box clipped{std::max(projected.x0, -L), std::max(projected.y0, -L),
                      std::min(projected.x1, L), std::min(projected.y1, L)};
    if (clipped.x0 < clipped.x1 && clipped.y0 < clipped.y1) shadows.push_back(clipped);
  }
  return 1.0 - union_area(shadows) / (4 * L * L);
}

Scene clipped_to_map(const Scene& scene) {
  Scene clipped = scene;
  clipped.occluders.clear();
  for (const Rect& r : scene.occluders) {
    const double half = scene.light.frustum_width * r.z / (2 * scene.light.near_plane);
    const Rect inside{std::max(r.x0, -half), std::max(r.y0, -half), std::min(r.x1, half),
                      std::min(r.y1, half), r.z};
    if (inside.x0 < inside.x1 && inside.y0 < inside.y1) clipped.occluders.push_back(inside);
  }
  return clipped;
}

FloatImage exact_visibility_image(const Scene& scene, const FloatImage& receivers) {
  FloatImage image(receivers.width, receivers.height, 1);
  for (int j = 0; j < receivers.height; ++j) {
    for (int i = 0; i < receivers.width; ++i) {
      const double z = receivers.at(i, j, 2);
      const UV slope = ray_slope(scene.light, receivers.at(i, j, 0), receivers.at(i, j, 1));
      image.at(i, j) = float(exact_visibility(scene, slope.u * z, slope.v * z, z));
    }
  }
  return image;
}

}  // namespace penumbra::reference
