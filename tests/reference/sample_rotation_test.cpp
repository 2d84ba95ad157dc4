// The `rotation` key's placement of a variant's samples per pixel: round
// sets turn, square sets shift on the square's torus, and pixel (0, 0) keeps
// the baked points (its noise is 0).
#include "penumbra/reference/sample_rotation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "penumbra/compiler/disk.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {
namespace {

VariantKeys ign() {
  return {.rotation = std::string(kIgnRotation)};
}

TEST(SampleRotation, RoundSetsTurnByThePixelsNoise) {
  const Disk disk = generate_disk({.count = 16, .seed = 1, .method = "sample_elimination"}).value();
  bool seam = false;
  EXPECT_EQ(placed_disk(disk, ign(), {.pixel_x = 0, .pixel_y = 0}, seam).points, disk.points);
  EXPECT_EQ(placed_disk(disk, {}, {.pixel_x = 7, .pixel_y = 3}, seam).points, disk.points);
  const Disk turned = placed_disk(disk, ign(), {.pixel_x = 7, .pixel_y = 3}, seam);
  const Disk other = placed_disk(disk, ign(), {.pixel_x = 8, .pixel_y = 3}, seam);
  EXPECT_FALSE(seam);
  EXPECT_NE(turned.points, other.points);
  // A turn: every point keeps its distance from the centre, and all turn alike.
  const double angle = std::atan2(turned.points[0][1], turned.points[0][0]) -
                       std::atan2(disk.points[0][1], disk.points[0][0]);
  for (std::size_t i = 0; i < disk.points.size(); ++i) {
    EXPECT_NEAR(std::hypot(turned.points[i][0], turned.points[i][1]),
                std::hypot(disk.points[i][0], disk.points[i][1]), 1e-6);
    const double c = std::cos(angle), s = std::sin(angle);
    EXPECT_NEAR(turned.points[i][0], disk.points[i][0] * c - disk.points[i][1] * s, 1e-6);
    EXPECT_NEAR(turned.points[i][1], disk.points[i][0] * s + disk.points[i][1] * c, 1e-6);
  }
}

TEST(SampleRotation, SquareSetsShiftOnTheTorusAndStayInTheSquare) {
  Disk square = generate_disk({.count = 64, .seed = 1, .method = "square_stratified"}).value();
  bool seam = false;
  const Disk shifted = placed_disk(square, ign(), {.pixel_x = 5, .pixel_y = 11}, seam);
  ASSERT_EQ(shifted.points.size(), square.points.size());
  double shift[2] = {0.0, 0.0};
  for (std::size_t i = 0; i < square.points.size(); ++i) {
    for (int axis = 0; axis < 2; ++axis) {
      const double moved = shifted.points[i][axis];
      EXPECT_GE(moved, -1.0);
      EXPECT_LT(moved, 1.0);
      // Every point moves by the same amount modulo the square's side.
      double delta = (moved - square.points[i][axis]) / 2.0;
      delta -= std::floor(delta);
      if (i == 0) shift[axis] = delta;
      EXPECT_NEAR(std::remainder(delta - shift[axis], 1.0), 0.0, 1e-6) << i;
    }
  }
  EXPECT_GT(shift[0] + shift[1], 0.0);
}

// A square sample the shift puts on the torus's seam may wrap either way in
// float32: the receiver is marked with rotation_seam, and only there.
TEST(SampleRotation, ASampleOnTheSeamMarksTheReceiver) {
  const int x = 3, y = 5;
  // The pixel's interleaved gradient noise, as sample_rotation.cpp has it.
  const double noise =
      std::fmod(52.984375 * std::fmod(0.067138671875 * x + 0.005859375 * y, 1.0), 1.0);
  VariantKeys keys = ign();
  keys.pcf_samples = 1;
  const FloatImage map(8, 8, 1, 20.0f);
  const Query q{.u = 0.5, .v = 0.5, .z = 10.0, .pixel_x = x, .pixel_y = y};
  for (const double offset : {0.0, 0.01}) {
    // (p + 1) / 2 + noise = 1 + offset / 2 on the first axis.
    const float p = float(1.0 - 2.0 * noise + offset);
    const Variant variant{"pcf_poisson",
                          Technique::pcf_poisson,
                          keys,
                          {},
                          Disk{"test", "square_stratified", 0, {{p, 0.25f}}, 0.0},
                          {},
                          {}};
    ASSERT_TRUE(check_variant(variant));
    EXPECT_EQ(evaluate(variant, ShadowMapView(map), {}, q).ambiguous,
              offset == 0.0 ? Ambiguity::rotation_seam : Ambiguity::none);
  }
}

}  // namespace
}  // namespace penumbra::reference
