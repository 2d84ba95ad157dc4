// Boxes and the report's stage: exact visibility of boxes against rays to a
// grid on the light, the ray cast through box sides, and the stage's view.
#include "penumbra/reference/stage.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

#include "penumbra/reference/accuracy_scenes.hpp"
#include "penumbra/reference/exact_visibility.hpp"

namespace penumbra::reference {
namespace {

// The fraction of a 400^2 grid of light points whose segment to P meets no
// occluder: sampled along the segment at every occluder depth for
// rectangles, and through the slab test for boxes (a segment q -> P meets a
// box where its z range overlaps the box's after clipping to z < P.z - bias).
double grid_visibility(const Scene& scene, const std::array<double, 3>& p) {
  constexpr int kSteps = 400;
  const double L = scene.light.light_world_size;
  const double limit = p[2] - scene.light.bias;
  int lit = 0;
  for (int b = 0; b < kSteps; ++b) {
    for (int a = 0; a < kSteps; ++a) {
      const double qx = -L + 2 * L * (a + 0.5) / kSteps, qy = -L + 2 * L * (b + 0.5) / kSteps;
      // The segment is (qx, qy, 0) + t (P - q), t in [0, 1]; z = t P.z.
      bool blocked = false;
      for (const Box& box : scene.boxes) {
        double lo = box.z0 / p[2], hi = std::min(box.z1, limit) / p[2];
        const auto slab = [&](double q, double d, double a0, double a1) {
          if (d == 0.0) {
            if (q < a0 || q >= a1) hi = -1.0;
            return;
          }
          const double t0 = (a0 - q) / d, t1 = (a1 - q) / d;
          lo = std::max(lo, std::min(t0, t1));
          hi = std::min(hi, std::max(t0, t1));
        };
        slab(qx, p[0] - qx, box.x0, box.x1);
        slab(qy, p[1] - qy, box.y0, box.y1);
        blocked = blocked || (box.z0 < limit && lo < hi);
      }
      for (const Rect& r : scene.occluders) {
        if (!(r.z < limit)) continue;
        const double x = qx + (p[0] - qx) * r.z / p[2], y = qy + (p[1] - qy) * r.z / p[2];
        blocked = blocked || (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1);
      }
      lit += blocked ? 0 : 1;
    }
  }
  return lit / double(kSteps * kSteps);
}

TEST(ExactVisibility, BoxesAgreeWithRaysToAGridOnTheLight) {
  const Stage stage = report_stage();
  // Ground points in the shadows of the pole, the standing block and the
  // slab (over the low block), one on the low block's top, one at the
  // standing block's foot.
  const std::vector<std::array<double, 3>> points = {
      {3.11, -3.77, 16.0}, {3.24, -2.66, 16.0}, {-3.81, -2.0, 16.0}, {-3.18, -0.58, 16.0},
      {-0.22, 0.28, 16.0}, {1.04, 1.71, 14.6},  {0.25, 1.76, 16.0},  {-2.1, -0.2, 16.0}};
  int partial = 0;
  for (const auto& p : points) {
    const double exact = exact_visibility(stage.scene, p[0], p[1], p[2]);
    // A 400^2 grid resolves the covered area to about its perimeter over 400.
    EXPECT_NEAR(exact, grid_visibility(stage.scene, p), 5e-3)
        << p[0] << ", " << p[1] << ", " << p[2];
    partial += exact > 0.01 && exact < 0.99 ? 1 : 0;
  }
  EXPECT_GE(partial, 6);  // most points are in a penumbra, where the shapes matter
}

TEST(ExactVisibility, AFlatBoxIsARectangle) {
  Scene flat, rect;
  flat.boxes = {{-0.3, -0.2, 0.4, 0.1, 8.0, 8.0}};
  rect.occluders = {{-0.3, -0.2, 0.4, 0.1, 8.0}};
  for (double x : {-0.5, 0.0, 0.2, 0.7}) {
    EXPECT_NEAR(exact_visibility(flat, x, 0.1, 16.0), exact_visibility(rect, x, 0.1, 16.0), 1e-12)
        << x;
  }
}

TEST(ExactVisibility, AShadowCoveringTheLightLeavesNone) {
  Scene scene;
  scene.boxes = {{-5.0, -5.0, 5.0, 5.0, 4.0, 6.0}};
  EXPECT_EQ(exact_visibility(scene, 0.3, -0.2, 16.0), 0.0);
}

TEST(RayCastDepth, BoxesShowTheirTopAndTheSideTheLightSees) {
  Scene scene;
  scene.light.near_plane = 1.0;
  scene.light.frustum_width = 2.0;  // the ray through texel u is x = (2u - 1) z
  scene.boxes = {{0.0, -1.0, 1.0, 1.0, 2.0, 4.0}};
  const FloatImage depth = ray_cast_depth(scene, 10, 2, 50.0);
  EXPECT_FLOAT_EQ(depth.at(6, 0), 2.0f);   // u = 0.65: x = 0.6 at z = 2, the top
  EXPECT_FLOAT_EQ(depth.at(3, 0), 50.0f);  // u = 0.35: x < 0 throughout
  EXPECT_FLOAT_EQ(depth.at(9, 0), 50.0f);  // u = 0.95: x > 1 by z = 2, past the box
  // A tall box beside the axis: the ray x = 0.7 z (u = 0.85) meets its side
  // x = 2 at z = 2.86, below its top at z = 2.
  scene.boxes = {{2.0, -5.0, 3.0, 5.0, 2.0, 8.0}};
  const FloatImage side = ray_cast_depth(scene, 10, 2, 50.0);
  EXPECT_NEAR(side.at(8, 0), 2.0 / 0.7, 1e-5);
}

TEST(Triangles, TwelvePerBox) {
  Scene scene;
  scene.boxes = {{0.0, 0.0, 1.0, 2.0, 3.0, 5.0}};
  const auto vertices = triangles(scene);
  ASSERT_EQ(vertices.size(), 36u);
  double area = 0.0;  // the surface: 2 (1 * 2 + 1 * 2 + 2 * 2) = 16
  for (std::size_t t = 0; t < vertices.size(); t += 3) {
    const auto& a = vertices[t];
    const auto& b = vertices[t + 1];
    const auto& c = vertices[t + 2];
    const std::array<double, 3> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const std::array<double, 3> v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double nx = u[1] * v[2] - u[2] * v[1], ny = u[2] * v[0] - u[0] * v[2],
                 nz = u[0] * v[1] - u[1] * v[0];
    area += std::sqrt(nx * nx + ny * ny + nz * nz) / 2;
  }
  EXPECT_NEAR(area, 16.0, 1e-6);
}

TEST(Stage, EveryMeasuredPixelIsInsideTheMapAndEverySurfaceShows) {
  const Stage stage = report_stage();
  const StageView v = view(stage, 160, 120);
  std::set<Surface> seen;
  for (int j = 0; j < 120; ++j) {
    for (int i = 0; i < 160; ++i) {
      const Surface s = v.surfaces[std::size_t(j) * 160 + i];
      seen.insert(s);
      if (s == Surface::none) continue;
      EXPECT_GT(v.receivers.at(i, j, 0), 0.0f);
      EXPECT_LT(v.receivers.at(i, j, 0), 1.0f);
      EXPECT_GT(v.receivers.at(i, j, 1), 0.0f);
      EXPECT_LT(v.receivers.at(i, j, 1), 1.0f);
    }
  }
  EXPECT_EQ(seen.size(), 4u);
  // Every box lies inside the map's frustum, so the map sees all it casts.
  for (const Box& b : stage.scene.boxes) {
    const double half = stage.scene.light.frustum_width * b.z0 / (2 * stage.scene.light.near_plane);
    EXPECT_GT(b.x0, -half);
    EXPECT_LT(b.x1, half);
    EXPECT_GT(b.y0, -half);
    EXPECT_LT(b.y1, half);
  }
}

TEST(Stage, TruthHasUmbraPenumbraAndLight) {
  const Stage stage = report_stage();
  const StageView v = view(stage, 160, 120);
  const FloatImage exact = exact_visibility_image(stage.scene, v);
  int umbra = 0, penumbra = 0, lit = 0;
  for (std::size_t i = 0; i < v.surfaces.size(); ++i) {
    if (!receives_light(v.surfaces[i])) continue;
    const float e = exact.data[i];
    (e == 0.0f ? umbra : e == 1.0f ? lit : penumbra) += 1;
  }
  EXPECT_GT(umbra, 50);
  EXPECT_GT(penumbra, 300);
  EXPECT_GT(lit, 2000);
}

// The accuracy suite: names as docs/accuracy.md lists them, everything a
// shadow can depend on inside the map, and a penumbra to measure.
TEST(AccuracyScenes, LieInsideTheirMapsAndHavePenumbrae) {
  std::vector<std::string> names;
  for (const Scene& scene : accuracy_scenes()) {
    names.push_back(scene.name);
    const auto half = [&](double z) {
      return scene.light.frustum_width * z / (2 * scene.light.near_plane);
    };
    for (const Rect& r : scene.occluders) {
      EXPECT_TRUE(r.x0 > -half(r.z) && r.x1 < half(r.z) && r.y0 > -half(r.z) && r.y1 < half(r.z))
          << scene.name;
    }
    for (const Box& b : scene.boxes) {
      EXPECT_TRUE(b.x0 > -half(b.z0) && b.x1 < half(b.z0) && b.y0 > -half(b.z0) &&
                  b.y1 < half(b.z0))
          << scene.name;
    }
    const StageView v = light_view(scene, scene.receivers_width, scene.receivers_height);
    const FloatImage exact = exact_visibility_image(scene, v);
    int penumbra = 0;
    for (float e : exact.data) penumbra += e > 0.0f && e < 1.0f ? 1 : 0;
    EXPECT_GT(penumbra, 200) << scene.name;
  }
  EXPECT_EQ(names,
            (std::vector<std::string>{"contact", "overlap", "thin", "large_light", "slope"}));
}

}  // namespace
}  // namespace penumbra::reference
