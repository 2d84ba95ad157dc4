// Exact ground truth: hand-computed areas of projected occluders on the light.
#include "penumbra/reference/exact_visibility.hpp"

#include <gtest/gtest.h>

#include <array>

namespace penumbra::reference {
namespace {

// L = 0.5 (light area 1); from P = (0, 0, 2) an occluder at z = 1 projects
// scaled by 2 / (2 - 1) = 2, one at z = 1.5 by 4.
Scene scene_with(std::vector<Rect> occluders) {
  Scene scene;
  scene.name = "hand";
  scene.occluders = std::move(occluders);
  scene.light.near_plane = 1.0;
  scene.light.frustum_width = 2.0;
  return scene;
}

const Rect kCentre{-0.125, -0.125, 0.125, 0.125, 1.0};  // projects to [-0.25, 0.25]^2

TEST(ExactVisibility, OneRectangle) {
  EXPECT_DOUBLE_EQ(exact_visibility(scene_with({kCentre}), 0.0, 0.0, 2.0), 0.75);
  // From x = 0.25: X = 0.25 + (x - 0.25) * 2 spans [-0.5, 0].
  EXPECT_DOUBLE_EQ(exact_visibility(scene_with({kCentre}), 0.25, 0.0, 2.0), 0.75);
  // From x = 0.5 it spans [-0.25, 0.25] - 0.5 + ... = [-0.75, -0.25]: clipped to [-0.5, -0.25].
  EXPECT_DOUBLE_EQ(exact_visibility(scene_with({kCentre}), 0.5, 0.0, 2.0), 1.0 - 0.25 * 0.5);
}

TEST(ExactVisibility, OverlappingRectanglesCountTheirUnionOnce) {
  // [0, 0.125] x [-0.0625, 0.0625] at z = 1.5 projects to [0, 0.5] x [-0.25, 0.25],
  // overlapping the first one on [0, 0.25] x [-0.25, 0.25]:
  // 0.25 + 0.25 - 0.125 = 0.375 covered.
  const Rect behind{0.0, -0.0625, 0.125, 0.0625, 1.5};
  EXPECT_DOUBLE_EQ(exact_visibility(scene_with({kCentre, behind}), 0.0, 0.0, 2.0), 0.625);
}

TEST(ExactVisibility, IgnoresRectanglesBehindTheReceiverOrWithinTheBias) {
  const Rect below{-5.0, -5.0, 5.0, 5.0, 3.0};
  EXPECT_DOUBLE_EQ(exact_visibility(scene_with({kCentre, below}), 0.0, 0.0, 2.0), 0.75);
  Scene biased = scene_with({kCentre, {-5.0, -5.0, 5.0, 5.0, 1.99}});
  EXPECT_DOUBLE_EQ(exact_visibility(biased, 0.0, 0.0, 2.0), 0.0);
  biased.light.bias = 0.05;
  EXPECT_DOUBLE_EQ(exact_visibility(biased, 0.0, 0.0, 2.0), 0.75);
}

TEST(ExactVisibility, LargeOccluderCoversTheWholeLight) {
  EXPECT_DOUBLE_EQ(exact_visibility(scene_with({{-1.0, -1.0, 1.0, 1.0, 1.0}}), 0.1, 0.2, 2.0), 0.0);
}

TEST(ExactVisibility, AgreesWithRaysToAGridOnTheLight) {
  // An independent reading: the fraction of light points q whose segment to
  // P meets no occluder, the segment crossing depth z at q + (P - q) z / z_P.
  const Scene scene = scene_with({{-0.3, -0.1, 0.2, 0.4, 0.8},
                                  {0.0, -0.5, 0.6, 0.1, 1.2},
                                  {-0.4, -0.4, -0.1, 0.0, 1.5},
                                  {0.1, 0.2, 0.3, 0.3, 1.7}});
  constexpr int kSteps = 400;
  for (const auto& p : {std::array<double, 3>{0.0, 0.0, 2.0}, {0.3, -0.2, 2.5}, {-0.5, 0.4, 1.9}}) {
    int lit = 0;
    for (int b = 0; b < kSteps; ++b) {
      for (int a = 0; a < kSteps; ++a) {
        const double qx = -0.5 + (a + 0.5) / kSteps, qy = -0.5 + (b + 0.5) / kSteps;
        bool blocked = false;
        for (const Rect& r : scene.occluders) {
          if (r.z >= p[2]) continue;
          const double x = qx + (p[0] - qx) * r.z / p[2], y = qy + (p[1] - qy) * r.z / p[2];
          blocked = blocked || (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1);
        }
        lit += blocked ? 0 : 1;
      }
    }
    // A grid of 400^2 points resolves the covered area to about its
    // perimeter over 400.
    EXPECT_NEAR(exact_visibility(scene, p[0], p[1], p[2]), lit / double(kSteps * kSteps), 5e-3)
        << p[0] << ", " << p[1] << ", " << p[2];
  }
}

TEST(ExactVisibility, ImageEvaluatesAtTheReceiverPoint) {
  // Pixel (1, 0): u = 0.625, v = 0.5, z_r = 2 is P = ((u - 0.5) Fw z / n, 0, 2) = (0.5, 0, 2).
  FloatImage receivers(2, 1, 3);
  receivers.at(0, 0, 0) = 0.5f;
  receivers.at(1, 0, 0) = 0.625f;
  for (int i = 0; i < 2; ++i) receivers.at(i, 0, 1) = 0.5f, receivers.at(i, 0, 2) = 2.0f;
  const FloatImage image = exact_visibility_image(scene_with({kCentre}), receivers);
  ASSERT_EQ(image.channels, 1);
  EXPECT_EQ(image.at(0, 0), 0.75f);
  EXPECT_EQ(image.at(1, 0), float(1.0 - 0.25 * 0.5));
}

}  // namespace
}  // namespace penumbra::reference
