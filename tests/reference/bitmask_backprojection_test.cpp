// bitmask_backprojection: hand-checked coverage of the light's N samples,
// the overlap the area sum counts twice counted once, and the sample layout
// against the exact area of one flat patch.
#include <gtest/gtest.h>

#include "fixtures.hpp"
#include "penumbra/reference/backprojection.hpp"

namespace penumbra::reference {
namespace {

Sample bitmask(const FloatImage& map, const Query& q, int bits,
               const LightParams& light = testing::unit_backprojection_light()) {
  return evaluate(testing::bitmask_backprojection_variant(bits), ShadowMapView(map), light, q);
}

void fill(FloatImage& map, int x0, int y0, int x1, int y1, float depth) {
  for (int j = y0; j <= y1; ++j) {
    for (int i = x0; i <= x1; ++i) map.at(i, j) = depth;
  }
}

TEST(BitmaskBackprojection, HalfAndQuarterOfTheLightAreExact) {
  for (int bits : kAllowedLightBits) {
    SCOPED_TRACE(bits);
    FloatImage half(8, 8, 1, 10.0f);
    fill(half, 3, 3, 4, 3, 1.0f);  // y in [-0.5, 0]
    EXPECT_EQ(bitmask(half, {0.5, 0.5, 2.0}, bits).visibility, 0.5);
    // One texel, [0, 0.5]^2: the net's points split evenly by halves.
    FloatImage quarter(8, 8, 1, 10.0f);
    fill(quarter, 4, 4, 4, 4, 1.0f);
    EXPECT_EQ(bitmask(quarter, {0.5, 0.5, 2.0}, bits).visibility, 0.75);
  }
}

TEST(BitmaskBackprojection, OverlapIsCountedOnce) {
  // Row 3 at z = 1 covers y in [-0.5, 0]; row 2 nearer the light (z = 6/7,
  // g = 1.5) projects to x in [-0.375, 0.375], y in [-0.75, -0.375]: inside
  // row 3's projection, so the covered light is still half.
  FloatImage map(8, 8, 1, 10.0f);
  fill(map, 3, 3, 4, 3, 1.0f);
  fill(map, 3, 2, 4, 2, float(6.0 / 7.0));
  const Sample sample = bitmask(map, {0.5, 0.5, 2.0}, 256);
  EXPECT_EQ(sample.ambiguous, Ambiguity::none);
  EXPECT_EQ(sample.visibility, 0.5);
  // The area sum adds row 2's 0.75 x 0.125 again.
  const double summed = evaluate(testing::backprojection_variant(), ShadowMapView(map),
                                 testing::unit_backprojection_light(), {0.5, 0.5, 2.0})
                            .visibility;
  EXPECT_NEAR(summed, 0.5 - 0.75 * 0.125, 1e-6);
}

// Over many receivers, one flat patch's covered fraction against its exact
// area: the Hammersley layout's error shrinks as 1 / N, not as a grid's 1 / sqrt(N).
TEST(BitmaskBackprojection, SamplesTrackTheExactAreaOfAPatch) {
  FloatImage map(64, 64, 1, 10.0f);
  fill(map, 20, 24, 43, 39, 1.0f);
  const ShadowMapView view(map);
  double worst[2] = {0.0, 0.0};
  for (int k = 0; k < 400; ++k) {
    const Query q{0.3 + 0.4 * (k % 20) / 19.0, 0.3 + 0.4 * (k / 20) / 19.0, 2.0};
    const TexelRect all{0, 0, 63, 63};
    const double exact = backprojection_visibility(
        backprojected_area(view, testing::unit_backprojection_light(), q, all),
        testing::unit_backprojection_light());
    int slot = 0;
    for (int bits : {64, 1024}) {
      const Sample sample = bitmask(map, q, bits);
      if (sample.ambiguous == Ambiguity::none)
        worst[slot] = std::max(worst[slot], std::abs(sample.visibility - exact));
      ++slot;
    }
  }
  EXPECT_LT(worst[0], 0.1);   // 64 samples: at most a few 1 / 64 steps off
  EXPECT_LT(worst[1], 0.02);  // 1024: a 32 x 32 grid is off by up to 1 / 32 on an edge
  EXPECT_LT(worst[1], worst[0]) << worst[0];
}

}  // namespace
}  // namespace penumbra::reference
