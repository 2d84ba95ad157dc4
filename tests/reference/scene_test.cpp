// The test scenes: hand-checked ray casting, receivers on their planes, the
// features the scenes promise, and ambiguity low enough to verify against.
#include "penumbra/reference/scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>

#include "fixtures.hpp"
#include "penumbra/reference/compare.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/reference/whitepaper_pcss.hpp"

namespace penumbra::reference {
namespace {

// n = 1, Fw = 2: u = 0.5 + x / (2 z), so texel centres are easy to place.
Scene simple_scene() {
  Scene scene;
  scene.name = "simple";
  scene.light.near_plane = 1.0;
  scene.light.frustum_width = 2.0;
  scene.occluders = {{0.0, 0.0, 0.25, 0.25, 1.0},  // u, v in [0.5, 0.625)
                     {0.0, 0.0, 1.0, 1.0, 2.0}};   // u, v in [0.5, 0.75), behind the first
  return scene;
}

TEST(RayCastDepth, HandValues) {
  const FloatImage depth = ray_cast_depth(simple_scene(), 8, 8, 50.0);
  // Texel centres u = (i + 0.5) / 8: i = 4, 5 fall in [0.5, 0.75), only 4 in [0.5, 0.625).
  for (int j = 0; j < 8; ++j) {
    for (int i = 0; i < 8; ++i) {
      const bool far_one = i >= 4 && i <= 5 && j >= 4 && j <= 5;
      const float expected = i == 4 && j == 4 ? 1.0f : far_one ? 2.0f : 50.0f;
      EXPECT_EQ(depth.at(i, j), expected) << i << ", " << j;
    }
  }
}

TEST(Triangles, TwoPerRectangleCoveringIt) {
  const Scene scene = simple_scene();
  const auto vertices = triangles(scene);
  ASSERT_EQ(vertices.size(), 12u);
  for (std::size_t r = 0; r < scene.occluders.size(); ++r) {
    const Rect& rect = scene.occluders[r];
    double area = 0.0;
    for (std::size_t t = 0; t < 2; ++t) {
      const auto& a = vertices[6 * r + 3 * t];
      const auto& b = vertices[6 * r + 3 * t + 1];
      const auto& c = vertices[6 * r + 3 * t + 2];
      for (const auto& p : {a, b, c}) EXPECT_EQ(p[2], float(rect.z));
      area += std::abs((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])) / 2;
    }
    EXPECT_NEAR(area, (rect.x1 - rect.x0) * (rect.y1 - rect.y0), 1e-6);
  }
}

TEST(Receivers, LieOnThePlaneAtPixelCentres) {
  for (const Scene& scene : builtin_scenes()) {
    const FloatImage image = receivers(scene, 37, 23);
    ASSERT_EQ(image.channels, 3);
    for (int j = 0; j < image.height; ++j) {
      for (int i = 0; i < image.width; ++i) {
        const double u = image.at(i, j, 0), v = image.at(i, j, 1), z = image.at(i, j, 2);
        EXPECT_FLOAT_EQ(float(u), float((i + 0.5) / 37));
        EXPECT_FLOAT_EQ(float(v), float((j + 0.5) / 23));
        // Back to light-view space: x = (u - 0.5) Fw z / n.
        const double x = (u - 0.5) * scene.light.frustum_width * z / scene.light.near_plane;
        const double y = (v - 0.5) * scene.light.frustum_width * z / scene.light.near_plane;
        EXPECT_NEAR(z, scene.plane_z0 + scene.plane_dzdx * x + scene.plane_dzdy * y, 1e-5);
        EXPECT_NEAR(project(scene.light, x, y, z).u, u, 1e-12) << "project() inverts the ray";
      }
    }
  }
}

TEST(BuiltinScenes, HaveThePromisedFeatures) {
  const auto scenes = builtin_scenes();
  ASSERT_GE(scenes.size(), 2u);
  std::set<std::string> names;
  bool tilted = false;
  bool overlapping = false;
  for (const Scene& scene : scenes) {
    names.insert(scene.name);
    tilted = tilted || scene.plane_dzdx != 0.0 || scene.plane_dzdy != 0.0;
    EXPECT_NE(scene.receivers_width, scene.map_width) << scene.name;
    std::set<double> heights;
    bool leaves_map = false;
    for (const Rect& r : scene.occluders) {
      heights.insert(r.z);
      const UV lo = project(scene.light, r.x0, r.y0, r.z);
      const UV hi = project(scene.light, r.x1, r.y1, r.z);
      leaves_map = leaves_map || lo.u < 0 || lo.v < 0 || hi.u > 1 || hi.v > 1;
      // Occluders stand well above the receiver, except a decal inside the
      // bias (custom_light), which the bias keeps from shadowing it.
      const bool decal = scene.plane_z0 - r.z < scene.light.bias;
      EXPECT_TRUE(r.z < scene.plane_z0 - 0.5 || decal) << scene.name << ": occluder at " << r.z;
      for (const Rect& s : scene.occluders) {
        const UV slo = project(scene.light, s.x0, s.y0, s.z);
        const UV shi = project(scene.light, s.x1, s.y1, s.z);
        overlapping = overlapping || (&r != &s && r.z < s.z && lo.u < shi.u && slo.u < hi.u &&
                                      lo.v < shi.v && slo.v < hi.v);
      }
    }
    EXPECT_GE(heights.size(), 4u) << scene.name;
    EXPECT_TRUE(leaves_map) << scene.name;
  }
  EXPECT_EQ(names.size(), scenes.size());
  EXPECT_TRUE(tilted);
  EXPECT_TRUE(overlapping);
}

TEST(BuiltinScenes, AmbiguityStaysUnderTheLimit) {
  // Verification fails a run with more than 2% ambiguous pixels: the
  // built-in scenes must leave room for a correct GPU.
  const std::vector<Point2> disk(whitepaper_poisson_disk().begin(),
                                 whitepaper_poisson_disk().end());
  for (const Variant& variant : {testing::hard_variant(), testing::pcss_variant(disk, disk),
                                 testing::pcss_minmax_variant(disk)}) {
    for (const Scene& scene : builtin_scenes()) {
      const FloatImage depth =
          ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z);
      const auto result =
          evaluate_image(variant, depth, scene.light,
                         receivers(scene, scene.receivers_width, scene.receivers_height));
      ASSERT_TRUE(result.ok());
      const auto& mask = result->ambiguous.data;
      const double fraction =
          double(mask.size() - std::count(mask.begin(), mask.end(), 0.0f)) / double(mask.size());
      EXPECT_LE(fraction, kMaxAmbiguousFraction / 2) << scene.name << ", " << variant.name;
    }
  }
}

// A mask holds per pixel the Ambiguity bits of its reasons: only those its
// technique marks, and on the built-in scenes each of them somewhere.
TEST(BuiltinScenes, MasksHoldTheReasonsOfTheirTechnique) {
  const std::vector<Point2> disk(whitepaper_poisson_disk().begin(),
                                 whitepaper_poisson_disk().end());
  Variant plane = testing::pcss_variant(disk, disk);
  plane.keys.receiver_plane = true;
  struct Case {
    Variant variant;
    Target target;
    Ambiguity marks;  // the reasons its technique may mark
    Ambiguity seen;   // those these scenes show
  };
  const Case cases[] = {
      {testing::hard_variant(), Target::spirv, Ambiguity::texel_boundary, Ambiguity::none},
      {testing::pcss_variant(disk, disk), Target::spirv, Ambiguity::texel_boundary,
       Ambiguity::texel_boundary},
      {testing::pcss_minmax_variant(disk), Target::spirv, Ambiguity::search_window_edge,
       Ambiguity::search_window_edge},
      {plane, Target::spirv, Ambiguity::texel_boundary | Ambiguity::depth_slope,
       Ambiguity::texel_boundary | Ambiguity::depth_slope},
      {testing::backprojection_variant(), Target::spirv, Ambiguity::area_edges,
       Ambiguity::area_edges},
      {testing::backprojection_variant(), Target::hlsl_dx9,
       Ambiguity::walk_decision | Ambiguity::area_edges,
       Ambiguity::walk_decision | Ambiguity::area_edges},
      {testing::bitmask_backprojection_variant(64), Target::hlsl_dx9,
       Ambiguity::light_sample_edge | Ambiguity::walk_truncated,
       Ambiguity::light_sample_edge | Ambiguity::walk_truncated},
  };
  for (const Case& c : cases) {
    Ambiguity seen = Ambiguity::none;
    for (const Scene& scene : builtin_scenes()) {
      const FloatImage depth =
          ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z);
      const auto result =
          evaluate_image(c.variant, depth, scene.light,
                         receivers(scene, scene.receivers_width, scene.receivers_height), {},
                         shader_limits(c.target));
      ASSERT_TRUE(result.ok());
      for (float code : result->ambiguous.data) {
        const auto bits = std::uint8_t(code);
        ASSERT_EQ(float(bits), code) << c.variant.name << " on " << scene.name;
        ASSERT_EQ(bits & ~std::uint8_t(c.marks), 0) << c.variant.name << " on " << scene.name;
        seen |= Ambiguity(bits);
      }
    }
    EXPECT_EQ(int(seen), int(c.seen)) << c.variant.name;
  }
}

}  // namespace
}  // namespace penumbra::reference
