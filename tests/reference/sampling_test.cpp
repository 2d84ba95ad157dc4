// Texel addressing, bilinear comparisons and the ambiguity rule, against
// values worked out by hand.
#include "penumbra/reference/sampling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fixtures.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {
namespace {

using testing::column_split_map;
using testing::hard_variant;

Sample hard_at(const FloatImage& map, double u, double v, double z, SamplingPrecision p = {}) {
  return evaluate(hard_variant(), ShadowMapView(map), LightParams{}, {u, v, z}, p);
}

TEST(Hard, TexelCentresReadTheirOwnTexel) {
  FloatImage map(4, 4, 1, 10.0f);
  map.at(1, 2) = 5.0f;
  EXPECT_EQ(hard_at(map, 1.5 / 4, 2.5 / 4, 7.0).visibility, 0.0);
  EXPECT_EQ(hard_at(map, 0.5 / 4, 2.5 / 4, 7.0).visibility, 1.0);
  EXPECT_EQ(hard_at(map, 1.5 / 4, 1.5 / 4, 7.0).visibility, 1.0);
  EXPECT_EQ(hard_at(map, 1.5 / 4, 2.5 / 4, 7.0).ambiguous, Ambiguity::none);
}

TEST(Hard, ComparisonIsLessEqual) {
  const FloatImage map(2, 2, 1, 10.0f);
  EXPECT_EQ(hard_at(map, 0.25, 0.25, 10.0).visibility, 1.0);    // z_r == depth: lit
  EXPECT_EQ(hard_at(map, 0.25, 0.25, 10.001).visibility, 0.0);  // behind: occluded
}

TEST(Hard, TexelEdgesBelongToTheTexelOnTheRight) {
  const FloatImage map = column_split_map(4, 4, 2, 5.0f, 10.0f);
  // u W = 2 exactly starts texel 2 (lit), and is ambiguous: texel 1 occludes.
  EXPECT_EQ(hard_at(map, 0.5, 0.3, 7.0).visibility, 1.0);
  EXPECT_EQ(hard_at(map, 0.5, 0.3, 7.0).ambiguous, Ambiguity::texel_boundary);
  EXPECT_EQ(hard_at(map, 0.4999, 0.3, 7.0).visibility, 0.0);
}

// An atlas tile's placement moves each sample by the shader's own rounding
// (SamplingPrecision::coordinate_error): the boundary's window widens by it.
TEST(Hard, CoordinateErrorWidensTheTexelBoundaryWindow) {
  const FloatImage map = column_split_map(4, 4, 2, 5.0f, 10.0f);
  const SamplingPrecision gpu;
  const double u = (2.0 + 2.0 * gpu.point_window()) / 4;  // just outside the GPU's own window
  EXPECT_EQ(hard_at(map, u, 0.3, 7.0, gpu).ambiguous, Ambiguity::none);
  SamplingPrecision atlas = gpu;
  atlas.coordinate_error = 2.0 * gpu.step();
  EXPECT_EQ(hard_at(map, u, 0.3, 7.0, atlas).ambiguous, Ambiguity::texel_boundary);
  EXPECT_EQ(hard_at(map, u, 0.3, 7.0, atlas).visibility, 1.0);
}

TEST(Hard, ReadsOutsideTheMapClampToTheEdge) {
  const FloatImage map = column_split_map(4, 4, 1, 5.0f, 10.0f);
  EXPECT_EQ(hard_at(map, -0.3, 0.5, 7.0).visibility, 0.0);
  EXPECT_EQ(hard_at(map, 1.7, 0.5, 7.0).visibility, 1.0);
  EXPECT_EQ(hard_at(map, -1e12, 1e12, 7.0).visibility, 0.0);
}

TEST(Hard, BiasAppliesToTheComparison) {
  const FloatImage map(2, 2, 1, 10.0f);
  LightParams light;
  EXPECT_EQ(evaluate(hard_variant(), ShadowMapView(map), light, {0.25, 0.25, 10.05}).visibility,
            0.0);
  light.bias = 0.1;
  EXPECT_EQ(evaluate(hard_variant(), ShadowMapView(map), light, {0.25, 0.25, 10.05}).visibility,
            1.0);
}

TEST(Ambiguity, FlagsExactlyTheWindowAroundADifferingBoundary) {
  // Columns 0-1 occlude, 2-3 do not: only the boundary at u W = 2 matters.
  const FloatImage map = column_split_map(4, 4, 2, 5.0f, 10.0f);
  for (int bits : {4, 8}) {
    const SamplingPrecision precision{bits};
    const double window = std::ldexp(1.0, -bits) + 1e-6;
    for (int k = 0; k <= 4 * 4096; ++k) {
      const double x = k / 4096.0;  // u W, exact in binary
      const bool expected = std::abs(x - 2.0) <= window;
      EXPECT_EQ(hard_at(map, x / 4, 0.3, 7.0, precision).ambiguous,
                ambiguous_if(expected, Ambiguity::texel_boundary))
          << "bits " << bits << ", u W = " << x;
    }
  }
}

TEST(Ambiguity, ConsidersBothAxes) {
  FloatImage map(4, 4, 1, 10.0f);
  map.at(1, 1) = 5.0f;  // one occluding texel; its corner (2, 2) touches three lit ones
  const double near_corner = (2.0 - 0.001) / 4;
  EXPECT_EQ(hard_at(map, near_corner, near_corner, 7.0).ambiguous, Ambiguity::texel_boundary);
  EXPECT_EQ(hard_at(map, near_corner, near_corner, 7.0).visibility, 0.0);
  // Near the corner (2, 2) only across v: texels (2, 1) and (2, 2) are both lit.
  EXPECT_EQ(hard_at(map, 2.5 / 4, near_corner, 7.0).ambiguous, Ambiguity::none);
}

TEST(CandidateTexels, ListsTheNearestFirst) {
  const FloatImage image(8, 8, 1);
  const ShadowMapView map(image);
  const TexelCandidates one = candidate_texels(map, 3.5 / 8, 3.5 / 8, 0.01);
  ASSERT_EQ(one.count, 1);
  EXPECT_EQ(one.texels[0].i, 3);
  const TexelCandidates four = candidate_texels(map, 4.995 / 8, 3.005 / 8, 0.01);
  ASSERT_EQ(four.count, 4);
  EXPECT_EQ(four.texels[0].i, 4);
  EXPECT_EQ(four.texels[0].j, 3);
  EXPECT_EQ(four.texels[3].i, 5);
  EXPECT_EQ(four.texels[3].j, 2);
  // At the map's edge both neighbours clamp to the same texel: no ambiguity.
  EXPECT_EQ(candidate_texels(map, 0.0, 0.5 / 8, 0.01).count, 1);
}

TEST(Bilinear, StepMapBlendsWithTheWeights) {
  // 2x2 map: column 0 occludes, column 1 is lit.
  const FloatImage image = column_split_map(2, 2, 1, 5.0f, 10.0f);
  const ShadowMapView map(image);
  EXPECT_DOUBLE_EQ(bilinear_compare(map, 0.25, 0.3, 7.0), 0.0);  // centre of texel 0
  EXPECT_DOUBLE_EQ(bilinear_compare(map, 0.5, 0.3, 7.0), 0.5);   // between the centres
  EXPECT_DOUBLE_EQ(bilinear_compare(map, 0.375, 0.3, 7.0), 0.25);
  EXPECT_DOUBLE_EQ(bilinear_compare(map, 0.75, 0.3, 7.0), 1.0);
  EXPECT_DOUBLE_EQ(bilinear_compare(map, 0.1, 0.3, 7.0), 0.0);  // clamped left
  EXPECT_DOUBLE_EQ(bilinear_compare(map, 0.9, 0.3, 7.0), 1.0);  // clamped right
}

TEST(Bilinear, BothAxesWeigh) {
  FloatImage image(2, 2, 1, 10.0f);
  image.at(0, 0) = 5.0f;
  const ShadowMapView map(image);
  EXPECT_DOUBLE_EQ(bilinear_compare(map, 0.5, 0.5, 7.0), 0.75);
  // (x, y) = (0.25, 0.75): texel (0, 0) weighs 0.75 * 0.25.
  EXPECT_DOUBLE_EQ(bilinear_compare(map, 0.375, 0.625, 7.0), 1.0 - 0.1875);
  EXPECT_DOUBLE_EQ(bilinear_compare(map, 0.5, 0.5, 4.0), 1.0);  // nothing occludes z = 4
}

TEST(Precision, Tolerances) {
  EXPECT_DOUBLE_EQ(tolerance(Technique::hard, {}), 1e-5);
  EXPECT_DOUBLE_EQ(tolerance(Technique::pcf_grid, {}), 2.0 / 256 + 1e-5);
  EXPECT_DOUBLE_EQ(tolerance(Technique::pcss, {4}), 2.0 / 16 + 1e-5);
}

TEST(Precision, BilinearToleranceCoversQuantizedCoordinates) {
  // The error model: a GPU that rounds or truncates texel coordinates to
  // `bits` fractional bits stays within the tolerance of the exact blend.
  std::mt19937 random(7);
  FloatImage image(16, 16, 1);
  for (float& depth : image.data) depth = random() % 2 ? 5.0f : 10.0f;
  const ShadowMapView map(image);
  const SamplingPrecision precision{8};
  const double bound = tolerance(Technique::pcf_grid, precision);
  std::uniform_real_distribution<double> uv(-0.1, 1.1);
  double worst = 0.0;
  for (int k = 0; k < 20000; ++k) {
    const double u = uv(random);
    const double v = uv(random);
    const double exact = bilinear_compare(map, u, v, 7.0);
    auto quantize = [&](double c, int size, auto round) {
      return round(c * size / precision.step()) * precision.step() / size;
    };
    for (auto round :
         {+[](double x) { return std::floor(x); }, +[](double x) { return std::nearbyint(x); }}) {
      const double gpu = bilinear_compare(map, quantize(u, 16, round), quantize(v, 16, round), 7.0);
      worst = std::max(worst, std::abs(gpu - exact));
    }
  }
  EXPECT_LE(worst, bound);
  EXPECT_GT(worst, bound / 4);  // the bound is not vacuous
}

}  // namespace
}  // namespace penumbra::reference
