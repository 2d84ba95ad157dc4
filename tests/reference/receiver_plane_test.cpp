// The receiver_plane key: the depth slope the query pass derives from screen
// derivatives, and a built-in scene where it changes what a filter sees (so
// that verify holds every target to it).
#include "penumbra/reference/receiver_plane.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "fixtures.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/reference/whitepaper_pcss.hpp"

namespace penumbra::reference {
namespace {

TEST(ReceiverPlane, SlopeInvertsTheScreenJacobian) {
  // u = 0.1 x, v = 0.2 y, z = 3 u + 5 v: dz/du = 3, dz/dv = 5 from any screen axes.
  const auto slope = depth_slope(0.1, 0.0, 0.3, 0.0, 0.2, 1.0, 100.0);
  EXPECT_NEAR(slope[0], 3.0, 1e-12);
  EXPECT_NEAR(slope[1], 5.0, 1e-12);
  // Screen axes turned against (u, v): the same plane.
  const auto turned = depth_slope(0.1, 0.1, 0.8, -0.1, 0.1, 0.2, 100.0);
  EXPECT_NEAR(turned[0], 3.0, 1e-12);
  EXPECT_NEAR(turned[1], 5.0, 1e-12);
  // No plane: a singular quad, a non-finite derivative, or a slope over the
  // limit in either axis.
  EXPECT_EQ(depth_slope(0.1, 0.1, 1.0, 0.1, 0.1, 1.0, 100.0), (std::array<double, 2>{0, 0}));
  EXPECT_EQ(depth_slope(0.1, 0.0, std::nan(""), 0.0, 0.2, 1.0, 100.0),
            (std::array<double, 2>{0, 0}));
  EXPECT_EQ(depth_slope(0.1, 0.0, 0.3, 0.0, 0.2, 1.0, 4.0), (std::array<double, 2>{0, 0}));
  // z = 5 u + 3 v: dz/du alone is over 4.
  EXPECT_EQ(depth_slope(0.1, 0.0, 0.5, 0.0, 0.2, 0.6, 4.0), (std::array<double, 2>{0, 0}));
}

TEST(ReceiverPlane, TheSlopeLimitIsATangentAcrossTheLightsView) {
  LightParams light;
  light.frustum_width = 4.0;
  light.near_plane = 8.0;
  // At z = 16 one unit of uv spans 4 / 8 * 16 = 8 across the view.
  EXPECT_DOUBLE_EQ(max_depth_slope(light, 16.0), kMaxPlaneTangent * 8.0);
}

// A receiver step (a box's top against the ground) seen by one quad is no
// plane; the tilted receivers of the built-in scenes are.
TEST(ReceiverPlane, AQuadAcrossADepthStepHasNoPlane) {
  LightParams light;
  FloatImage step(2, 2, 3);
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i) {
      step.at(i, j, 0) = 0.5f + 0.001f * float(i);
      step.at(i, j, 1) = 0.5f + 0.001f * float(j);
      step.at(i, j, 2) = i == 0 ? 12.5f : 16.0f;
    }
  }
  for (const auto& slope : depth_slope_candidates(step, 0, 0, light)) {
    EXPECT_EQ(slope, (std::array<double, 2>{0, 0}));
  }
  const auto scenes = builtin_scenes();
  for (const Scene& scene : scenes) {
    const FloatImage image = receivers(scene, scene.receivers_width, scene.receivers_height);
    for (const auto& slope : depth_slope_candidates(image, 40, 40, scene.light)) {
      EXPECT_LT(std::abs(slope[0]), max_depth_slope(scene.light, image.at(40, 40, 2)))
          << scene.name;
    }
  }
}

TEST(ReceiverPlane, ChangesTheFilterWhereAnOccluderCrossesTheReceiver) {
  const auto scenes = builtin_scenes();
  const Scene& scene = *std::find_if(scenes.begin(), scenes.end(),
                                     [](const Scene& s) { return s.name == "tilted_overlap"; });
  const FloatImage depth = ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z);
  const FloatImage image = receivers(scene, scene.receivers_width, scene.receivers_height);
  const std::vector<Point2> disk(whitepaper_poisson_disk().begin(),
                                 whitepaper_poisson_disk().end());
  Variant plane = testing::poisson_variant(disk);
  plane.keys.receiver_plane = true;
  const auto flat = evaluate_image(testing::poisson_variant(disk), depth, scene.light, image);
  const auto sloped = evaluate_image(plane, depth, scene.light, image);
  ASSERT_TRUE(flat.ok() && sloped.ok());
  int changed = 0;
  int ambiguous = 0;
  for (std::size_t k = 0; k < flat->visibility.data.size(); ++k) {
    changed += std::abs(flat->visibility.data[k] - sloped->visibility.data[k]) > 0.05f ? 1 : 0;
    ambiguous += sloped->ambiguous.data[k] > 0.0f ? 1 : 0;
  }
  EXPECT_GT(changed, 20);
  EXPECT_LT(ambiguous, int(flat->visibility.data.size() / 100));
}

}  // namespace
}  // namespace penumbra::reference
