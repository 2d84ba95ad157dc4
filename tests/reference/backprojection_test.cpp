// backprojection: hand-checked projections of texel patches onto the light,
// and the culling window proved exact against a sum over every texel.
#include "penumbra/reference/backprojection.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "fixtures.hpp"

namespace penumbra::reference {
namespace {

FloatImage patch_map(int x0, int y0, int x1, int y1, float depth) {
  FloatImage map(8, 8, 1, 10.0f);
  for (int j = y0; j <= y1; ++j) {
    for (int i = x0; i <= x1; ++i) map.at(i, j) = depth;
  }
  return map;
}

double visibility(const FloatImage& map, const Query& q,
                  const LightParams& light = testing::unit_backprojection_light()) {
  return evaluate(testing::backprojection_variant(), ShadowMapView(map), light, q).visibility;
}

TEST(Backprojection, OccluderCoveringTheLightExactlyGivesZero) {
  EXPECT_EQ(visibility(patch_map(3, 3, 4, 4, 1.0f), {0.5, 0.5, 2.0}), 0.0);
}

TEST(Backprojection, OccluderCoveringHalfTheLightGivesHalf) {
  // Row 3 alone: y in [-0.5, 0].
  EXPECT_EQ(visibility(patch_map(3, 3, 4, 3, 1.0f), {0.5, 0.5, 2.0}), 0.5);
  // One texel: a quarter.
  EXPECT_EQ(visibility(patch_map(4, 4, 4, 4, 1.0f), {0.5, 0.5, 2.0}), 0.75);
}

TEST(Backprojection, ProjectionDependsOnDepthAndReceiver) {
  // At z = 4/3, g = 4: texel 4 (slopes 0..0.25) covers X in [0, 1], of which
  // [0, 0.5] is light: half in x, and row 4 gives y in [0, 1] -> [0, 0.5].
  EXPECT_NEAR(visibility(patch_map(4, 4, 4, 4, float(4.0 / 3.0)), {0.5, 0.5, 2.0}), 0.75, 1e-6);
  // From a receiver at slope 0.25 (u = 0.625), texels 3..4 at z = 1 project to
  // X = (a - 0.25) * 2 in [-1, 0]: half the light in x.
  EXPECT_EQ(visibility(patch_map(3, 3, 4, 4, 1.0f), {0.625, 0.5, 2.0}), 0.5);
}

TEST(Backprojection, OverlappingProjectionsClampAtZero) {
  // Texels 2..5 project to [-1, 1] in x: twice the light's width, clipped.
  EXPECT_EQ(visibility(patch_map(2, 3, 5, 4, 1.0f), {0.5, 0.5, 2.0}), 0.0);
}

TEST(Backprojection, OnlyOccludingTexelsInFrontOfTheReceiverCount) {
  // The bias keeps z = 1.95 from occluding z_r = 2.
  LightParams light = testing::unit_backprojection_light();
  light.bias = 0.1;
  EXPECT_EQ(visibility(patch_map(3, 3, 4, 4, 1.95f), {0.5, 0.5, 2.0}, light), 1.0);
  // A negative bias makes a texel behind the receiver "occlude"; it cannot
  // be projected towards the light and adds nothing.
  light.bias = -0.5;
  EXPECT_EQ(visibility(patch_map(3, 3, 4, 4, 2.2f), {0.5, 0.5, 2.0}, light), 1.0);
  // So is one at the receiver's depth (g(z_r) is infinite), while texels in
  // front still count: column 3 alone covers half the light.
  EXPECT_EQ(visibility(patch_map(3, 3, 4, 4, 2.0f), {0.5, 0.5, 2.0}, light), 1.0);
  FloatImage mixed = patch_map(3, 3, 3, 4, 1.0f);
  mixed.at(4, 3) = 2.0f;
  mixed.at(4, 4) = 2.1f;
  EXPECT_EQ(visibility(mixed, {0.5, 0.5, 2.0}, light), 0.5);
}

// Sums over every texel and over the culling window agree to 1e-12, with
// receivers all over and beyond the map and lights of several sizes.
class BackprojectionWindow : public ::testing::TestWithParam<double> {};

TEST_P(BackprojectionWindow, CullsOnlyTexelsThatMissTheLight) {
  LightParams light = testing::unit_backprojection_light();
  light.light_world_size = GetParam();
  std::mt19937 generator(17);
  std::uniform_real_distribution<double> uv(-0.1, 1.1), depth(2.0, 3.0);
  int culled = 0, shadowed = 0;
  for (unsigned seed = 0; seed < 4; ++seed) {
    const FloatImage image = seed % 2 == 0
                                 ? testing::random_map(40, 30, 1.0f, 1.9f, seed)
                                 : testing::blocky_map(40, 30, 12, 1.0f, 1.9f, 5.0f, seed);
    const ShadowMapView map(image);
    const MinMaxMip mip(map);
    const TexelRect all{0, 0, map.width() - 1, map.height() - 1};
    for (int k = 0; k < 300; ++k) {
      const Query q{uv(generator), uv(generator), depth(generator)};
      const double zlo = mip.node(mip.top_level(), 0, 0).min;
      const TexelRect window = backprojection_window(map, light, q, zlo);
      const double everything =
          backprojection_visibility(backprojected_area(map, light, q, all), light);
      const double windowed =
          backprojection_visibility(backprojected_area(map, light, q, window), light);
      ASSERT_NEAR(windowed, everything, 1e-12) << "receiver " << q.u << ", " << q.v << ", " << q.z;
      ASSERT_EQ(evaluate(testing::backprojection_variant(), map, mip, light, q).visibility,
                windowed);
      culled += window.count() < all.count() / 2;
      shadowed += everything < 1.0;
    }
  }
  EXPECT_GT(culled, 300) << "the window should cull most texels for most receivers";
  EXPECT_GT(shadowed, 300) << "too few receivers see any occluder";
}

INSTANTIATE_TEST_SUITE_P(LightSizes, BackprojectionWindow, ::testing::Values(0.02, 0.1, 0.3),
                         [](const auto& param_info) {
                           return "L" + std::to_string(int(param_info.param * 100));
                         });

// A target's cap on the walk (hlsl_dx9): the reference then walks the
// shader's nodes (or texels, brute force) itself. A cap the walk never
// reaches gives the texel-by-texel sum. Where it binds, brute force stops
// short, so less area is summed and more light seen; the min-max walk
// finishes from coarser levels instead, and stays near the sum.
TEST(BackprojectionCapped, WalkEqualsTheSumUnlessTheCapBinds) {
  LightParams light = testing::unit_backprojection_light();
  light.light_world_size = 0.3;
  std::mt19937 generator(5);
  std::uniform_real_distribution<double> uv(0.0, 1.0), depth(2.0, 3.0);
  for (const bool brute_force : {false, true}) {
    Variant variant = testing::backprojection_variant();
    if (brute_force) variant.keys.traversal = std::string(kBruteForceTraversal);
    const int own = walk_step_bound(variant).value();
    int cut_short = 0;
    double error = 0.0;
    for (unsigned seed = 0; seed < 4; ++seed) {
      const FloatImage image = testing::blocky_map(40, 30, 12, 1.0f, 1.9f, 5.0f, seed);
      const ShadowMapView map(image);
      const MinMaxMip mip(map);
      for (int k = 0; k < 200; ++k) {
        const Query q{uv(generator), uv(generator), depth(generator)};
        const Sample uncapped = evaluate(variant, map, mip, light, q);
        const double whole = uncapped.visibility;
        const Sample uncut = evaluate(variant, map, mip, light, q, {}, {own - 1});
        ASSERT_NEAR(uncut.visibility, whole, 1e-9) << "receiver " << q.u << ", " << q.v;
        // No close decision of the walk counts; its patches' edges as uncapped.
        EXPECT_EQ(uncut.ambiguous, uncapped.ambiguous);
        const Sample cut = evaluate(variant, map, mip, light, q, {}, {32});
        if (brute_force) {
          ASSERT_GE(cut.visibility, whole - 1e-9) << "receiver " << q.u << ", " << q.v;
        }
        cut_short += std::abs(cut.visibility - whole) > 1e-6;
        error += std::abs(cut.visibility - whole);
      }
    }
    SCOPED_TRACE(brute_force ? "brute force" : "walk");
    EXPECT_GT(cut_short, 50);
    // Mean errors at 32 steps: 0.32 where brute force stops, 0.043 where the
    // walk finishes.
    EXPECT_LT(error / 800, brute_force ? 0.5 : 0.06);
  }
}

// The cap binds at 8 steps: the walk takes the 2 x 2 roots of the window
// whole (8 steps left after the first would be needed to descend), each as
// one patch at its min depth, half of it since some of its texels do not
// occlude. With 224 steps the walk runs its course and gives the sum.
TEST(BackprojectionCapped, WalkFinishesFromCoarserLevels) {
  // Texels 3..4 at z = 1 cover the light exactly (unit_backprojection_light),
  // a quarter each; the window is texels 2..6, its roots the level-2 nodes.
  FloatImage diagonal(8, 8, 1, 10.0f);
  diagonal.at(3, 3) = 1.0f;
  diagonal.at(4, 4) = 1.0f;
  const Query q{0.5, 0.5, 2.0};
  const LightParams light = testing::unit_backprojection_light();
  const Variant variant = testing::backprojection_variant();
  auto at_cap = [&](const FloatImage& image, int steps) {
    return evaluate(variant, ShadowMapView(image), light, q, {}, {steps}).visibility;
  };
  // Roots (0, 0) and (1, 1): half of [-2, 0]^2 and [0, 2]^2 inside the light.
  EXPECT_EQ(at_cap(diagonal, 8), 0.75);
  EXPECT_EQ(at_cap(diagonal, 224), 0.5);
  // The other two texels deeper (g(1.5) = 6): every root is partly
  // occluding, and the sum covers the light.
  FloatImage full = diagonal;
  full.at(4, 3) = 1.5f;
  full.at(3, 4) = 1.5f;
  EXPECT_EQ(at_cap(full, 8), 0.5);
  EXPECT_EQ(at_cap(full, 224), 0.0);
}

TEST(CheckVariant, BackprojectionKeys) {
  Variant variant = testing::backprojection_variant();
  EXPECT_TRUE(check_variant(variant));
  variant.keys.max_nodes = 1;
  EXPECT_TRUE(check_variant(variant));
  variant.keys.max_nodes = 1 << 20;
  EXPECT_TRUE(check_variant(variant));
  variant.keys.max_nodes = 0;
  EXPECT_FALSE(check_variant(variant));
  variant.keys.max_nodes = (1 << 20) + 1;
  EXPECT_FALSE(check_variant(variant));
  variant.keys.max_nodes.reset();
  variant.keys.traversal = "brute_force";
  EXPECT_TRUE(check_variant(variant));
  variant.keys.traversal = "stack";
  EXPECT_FALSE(check_variant(variant));
}

}  // namespace
}  // namespace penumbra::reference
