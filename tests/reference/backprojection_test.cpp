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
// reaches gives the texel-by-texel sum; a small one stops it short, so
// less area is summed and more light seen.
TEST(BackprojectionCapped, WalkEqualsTheSumUnlessTheCapStopsIt) {
  LightParams light = testing::unit_backprojection_light();
  light.light_world_size = 0.3;
  std::mt19937 generator(5);
  std::uniform_real_distribution<double> uv(0.0, 1.0), depth(2.0, 3.0);
  for (const bool brute_force : {false, true}) {
    Variant variant = testing::backprojection_variant();
    if (brute_force) variant.keys.traversal = std::string(kBruteForceTraversal);
    const int own = walk_step_bound(variant).value();
    int stopped_short = 0;
    for (unsigned seed = 0; seed < 4; ++seed) {
      const FloatImage image = testing::blocky_map(40, 30, 12, 1.0f, 1.9f, 5.0f, seed);
      const ShadowMapView map(image);
      const MinMaxMip mip(map);
      for (int k = 0; k < 200; ++k) {
        const Query q{uv(generator), uv(generator), depth(generator)};
        const double whole = evaluate(variant, map, mip, light, q).visibility;
        const Sample uncut = evaluate(variant, map, mip, light, q, {}, {own - 1});
        ASSERT_NEAR(uncut.visibility, whole, 1e-9) << "receiver " << q.u << ", " << q.v;
        EXPECT_FALSE(uncut.ambiguous);
        const Sample cut = evaluate(variant, map, mip, light, q, {}, {8});
        ASSERT_GE(cut.visibility, whole - 1e-9) << "receiver " << q.u << ", " << q.v;
        stopped_short += cut.visibility > whole + 1e-6;
      }
    }
    EXPECT_GT(stopped_short, 50) << (brute_force ? "brute force" : "walk");
  }
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
