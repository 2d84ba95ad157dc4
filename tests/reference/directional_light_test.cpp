// An orthographic map's directional light: its parallel map rays, its
// exact visibility against a grid of ray directions, and PCSS's
// directional search and penumbra, pcss_minmax's and back-projection's
// against that truth.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "fixtures.hpp"
#include "penumbra/compiler/disk.hpp"
#include "penumbra/reference/exact_visibility.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/reference/stage.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {
namespace {

Scene directional(Scene scene) {
  return for_map_encoding(std::move(scene), MapEncoding::orthographic);
}

// The fraction of a 400^2 grid of ray slopes s in [-L, L]^2 whose ray to P,
// (P.x - s_x (P.z - z), P.y - s_y (P.z - z), z) for z < P.z, meets no
// occluder nearer than P.z - bias: rectangles at their depth, boxes by the
// slab test along z.
double grid_visibility(const Scene& scene, const std::array<double, 3>& p) {
  constexpr int kSteps = 400;
  const double L = scene.light.light_world_size;
  const double limit = p[2] - scene.light.bias;
  int lit = 0;
  for (int b = 0; b < kSteps; ++b) {
    for (int a = 0; a < kSteps; ++a) {
      const double sx = -L + 2 * L * (a + 0.5) / kSteps, sy = -L + 2 * L * (b + 0.5) / kSteps;
      const auto at = [&](double z) {
        return std::array<double, 2>{p[0] - sx * (p[2] - z), p[1] - sy * (p[2] - z)};
      };
      bool blocked = false;
      for (const Rect& r : scene.occluders) {
        if (!(r.z < limit)) continue;
        const auto q = at(r.z);
        blocked = blocked || (q[0] >= r.x0 && q[0] < r.x1 && q[1] >= r.y0 && q[1] < r.y1);
      }
      for (const Box& box : scene.boxes) {
        // x is affine in z along the ray: the z range inside each slab.
        double lo = box.z0, hi = std::min(box.z1, limit);
        const auto slab = [&](double slope, double from, double a0, double a1) {
          // coordinate(z) = from - slope (P.z - z) = (from - slope P.z) + slope z.
          const double c = from - slope * p[2];
          if (slope == 0.0) {
            if (c < a0 || c >= a1) hi = -1.0;
            return;
          }
          const double z0 = (a0 - c) / slope, z1 = (a1 - c) / slope;
          lo = std::max(lo, std::min(z0, z1));
          hi = std::min(hi, std::max(z0, z1));
        };
        slab(sx, p[0], box.x0, box.x1);
        slab(sy, p[1], box.y0, box.y1);
        blocked = blocked || (box.z0 < limit && lo < hi);
      }
      lit += blocked ? 0 : 1;
    }
  }
  return lit / double(kSteps * kSteps);
}

TEST(DirectionalLight, MapRaysAreParallelAndInvertProject) {
  const Scene scene = directional(builtin_scenes().front());
  ASSERT_TRUE(scene.light.orthographic());
  for (const double z : {10.0, 16.0, 31.0}) {
    const MapRay ray = map_ray(scene.light, 0.3, 0.8);
    EXPECT_EQ(ray.slope.u, 0.0);
    EXPECT_EQ(ray.slope.v, 0.0);
    const UV uv = project(scene.light, ray.at(z).u, ray.at(z).v, z);
    EXPECT_NEAR(uv.u, 0.3, 1e-12);
    EXPECT_NEAR(uv.v, 0.8, 1e-12);
  }
  // The box spans the perspective frustum's width at the receiver plane.
  const Scene perspective = builtin_scenes().front();
  EXPECT_DOUBLE_EQ(
      scene.light.frustum_width,
      perspective.light.frustum_width * perspective.plane_z0 / perspective.light.near_plane);
}

TEST(DirectionalLight, ReceiversAndTheRayCastMapFollowParallelRays) {
  Scene scene = directional(builtin_scenes()[1]);  // the tilted receiver
  const FloatImage points = receivers(scene, 40, 30);
  for (const auto [i, j] : {std::array{0, 0}, std::array{39, 29}, std::array{17, 11}}) {
    const double x = (points.at(i, j, 0) - 0.5) * scene.light.frustum_width;
    const double y = (points.at(i, j, 1) - 0.5) * scene.light.frustum_width;
    EXPECT_NEAR(points.at(i, j, 2), scene.plane_z0 + scene.plane_dzdx * x + scene.plane_dzdy * y,
                1e-5);
  }
  // One occluder: every texel whose centre's x, y lies inside it holds its
  // depth, whatever that depth, as a parallel projection draws it.
  scene.occluders = {{-1.0, -1.0, 1.0, 0.5, 11.0}};
  scene.boxes.clear();
  const FloatImage depth = ray_cast_depth(scene, 64, 64, scene.far_z);
  for (int j = 0; j < 64; ++j) {
    for (int i = 0; i < 64; ++i) {
      const double x = ((i + 0.5) / 64 - 0.5) * scene.light.frustum_width;
      const double y = ((j + 0.5) / 64 - 0.5) * scene.light.frustum_width;
      const bool inside = x >= -1.0 && x < 1.0 && y >= -1.0 && y < 0.5;
      EXPECT_EQ(depth.at(i, j), inside ? 11.0f : float(scene.far_z)) << i << ", " << j;
    }
  }
}

TEST(DirectionalLight, ExactVisibilityAgreesWithAGridOfDirections) {
  Stage stage = report_stage();
  stage.scene = directional(stage.scene);
  Scene with_rects = stage.scene;
  with_rects.occluders = {{-0.5, -0.5, 0.5, 0.2, 13.0}, {0.0, 0.0, 1.5, 1.0, 15.0}};
  // Ground points in the shadows of the pole, the standing block and the
  // slab, on the low block's top, and under the rectangles.
  for (const auto& p : {std::array<double, 3>{2.3, -1.9, 16.0},
                        {-2.0, -1.0, 16.0},
                        {0.2, 0.9, 16.0},
                        {1.1, 1.2, 14.6},
                        {0.3, 0.1, 16.0}}) {
    // 400^2 directions resolve the covered area to about its perimeter
    // over 400.
    EXPECT_NEAR(exact_visibility(with_rects, p[0], p[1], p[2]), grid_visibility(with_rects, p),
                5e-3)
        << p[0] << ", " << p[1] << ", " << p[2];
  }
}

TEST(DirectionalLight, StageTruthHasUmbraPenumbraAndLight) {
  Stage stage = report_stage();
  stage.scene = directional(stage.scene);
  const StageView v = view(stage, 160, 120);
  const FloatImage exact = exact_visibility_image(stage.scene, v);
  int umbra = 0, penumbra = 0, lit = 0;
  for (std::size_t i = 0; i < v.surfaces.size(); ++i) {
    if (!receives_light(v.surfaces[i])) continue;
    const float e = exact.data[i];
    (e == 0.0f ? umbra : e == 1.0f ? lit : penumbra) += 1;
    EXPECT_GT(v.receivers.data[3 * i], 0.0f);
    EXPECT_LT(v.receivers.data[3 * i], 1.0f);
  }
  EXPECT_GT(umbra, 50);
  EXPECT_GT(penumbra, 150);  // narrower than the area light's: 201 measured
  EXPECT_GT(lit, 2000);
}

// Mean |variant - truth| over a scene's receivers, on its ray-cast map.
double mean_error(const Variant& variant, const Scene& scene) {
  const FloatImage depth = ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z);
  const FloatImage points = receivers(scene, scene.receivers_width, scene.receivers_height);
  const FloatImage truth = exact_visibility_image(scene, points);
  const auto result = evaluate_image(variant, depth, scene.light, points);
  EXPECT_TRUE(result.ok()) << result.error().to_string();
  if (!result.ok()) return 1.0;
  double sum = 0.0;
  for (std::size_t k = 0; k < truth.data.size(); ++k) {
    sum += std::abs(double(result->visibility.data[k]) - truth.data[k]);
  }
  return sum / double(truth.data.size());
}

TEST(DirectionalLight, PcssIsAsCloseToTheTruthAsUnderTheAreaLight) {
  // PCSS's directional search and penumbra width (docs/techniques.md, "Map
  // encodings") approximate the directional truth as well as the
  // whitepaper's similar triangles do the area light's (measured 0.57, 0.65
  // and 0.42 times its mean error). The perspective formula's penumbra on
  // the same map is about n / (z_b z_r) times as wide: 2.0 to 2.6 times.
  const Disk disk = whitepaper16();
  const Variant pcss = testing::pcss_variant(disk.points, disk.points);
  for (const Scene& scene : builtin_scenes()) {
    const double area = mean_error(pcss, scene);
    const double directional_error = mean_error(pcss, directional(scene));
    std::printf("%-16s pcss mean error: area light %.5f, directional %.5f\n", scene.name.c_str(),
                area, directional_error);
    EXPECT_LT(directional_error, 1.5 * area) << scene.name;
  }
}

TEST(DirectionalLight, MinmaxTechniquesAreAsCloseToTheTruthAsUnderTheAreaLight) {
  // Back-projection into the square of directions, and pcss_minmax's
  // directional search and penumbra (docs/techniques.md, "Map encodings"),
  // against the directional truth, as under the area light against its own
  // (measured 0.4 to 0.8 times its mean error). The perspective geometry on
  // the same map errs 3.7 to 9.7 times as much as the directional one.
  const Disk disk = whitepaper16();
  const Variant variants[] = {testing::backprojection_variant(),
                              testing::bitmask_backprojection_variant(256),
                              testing::pcss_minmax_variant(disk.points)};
  for (const Variant& variant : variants) {
    for (const Scene& scene : builtin_scenes()) {
      const double area = mean_error(variant, scene);
      const double directional_error = mean_error(variant, directional(scene));
      std::printf("%-24s %-16s mean error: area light %.5f, directional %.5f\n",
                  variant.name.c_str(), scene.name.c_str(), area, directional_error);
      EXPECT_LT(directional_error, 1.5 * area + 1e-3) << variant.name << " " << scene.name;
    }
  }
}

}  // namespace
}  // namespace penumbra::reference
