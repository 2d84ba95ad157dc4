// The pcss reference against the NVIDIA PCSS whitepaper's own code on the built-in
// scenes: two independent readings of one specification must agree.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fixtures.hpp"
#include "penumbra/compiler/disk.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/reference/whitepaper_pcss.hpp"

namespace penumbra::reference {
namespace {

TEST(WhitepaperPcss, DiskIsTheWhitepapersPointForPoint) {
  const auto& disk = whitepaper_poisson_disk();
  EXPECT_EQ(disk[0], (Point2{-0.94201624f, -0.39906216f}));
  EXPECT_EQ(disk[7], (Point2{0.97484398f, 0.75648379f}));
  EXPECT_EQ(disk[15], (Point2{0.14383161f, -0.14100790f}));
}

TEST(WhitepaperPcss, EarlyOutAndFullShadow) {
  const FloatImage empty(64, 64, 1, 20.0f);
  EXPECT_EQ(whitepaper_pcss(ShadowMapView(empty), 0.5, 0.5, 15.0), 1.0);
  const FloatImage covered(64, 64, 1, 10.0f);
  EXPECT_EQ(whitepaper_pcss(ShadowMapView(covered), 0.5, 0.5, 15.0), 0.0);
}

TEST(WhitepaperPcss, EvaluateMatchesTheWhitepaperOnBuiltinScenes) {
  const std::vector<Point2> disk(whitepaper_poisson_disk().begin(),
                                 whitepaper_poisson_disk().end());
  const Variant variant = testing::pcss_variant(disk, disk);
  for (const Scene& scene : builtin_scenes()) {
    // The transliteration has the whitepaper's constants: only its light applies.
    const LightParams& l = scene.light;
    if (l.light_world_size != 0.5 || l.frustum_width != 3.75 || l.near_plane != 9.5 ||
        l.bias != 0.0) {
      continue;
    }
    const FloatImage depth = ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z);
    const FloatImage points = receivers(scene, scene.receivers_width, scene.receivers_height);
    const ShadowMapView map(depth);
    int penumbra = 0;
    int umbra = 0;
    double worst = 0.0;
    for (int j = 0; j < points.height; ++j) {
      for (int i = 0; i < points.width; ++i) {
        const Query q{points.at(i, j, 0), points.at(i, j, 1), points.at(i, j, 2)};
        const double ours = evaluate(variant, map, scene.light, q).visibility;
        const double theirs = whitepaper_pcss(map, q.u, q.v, q.z);
        worst = std::max(worst, std::abs(ours - theirs));
        penumbra += ours > 0.0 && ours < 1.0;
        umbra += ours == 0.0;
      }
    }
    EXPECT_LE(worst, 1e-12) << scene.name;
    // The scene exercises the interesting cases, not only the early out.
    EXPECT_GT(penumbra, 1000) << scene.name;
    EXPECT_GT(umbra, 100) << scene.name;
  }
}

// The compiler bakes whitepaper16 into shaders; the transliteration keeps its
// own copy of the whitepaper's table. They must agree point for point.
TEST(WhitepaperDisk, CompilerCopyEqualsTheTransliterationsCopy) {
  const Disk baked = whitepaper16();
  const auto& paper = whitepaper_poisson_disk();
  ASSERT_EQ(baked.points.size(), paper.size());
  for (std::size_t i = 0; i < paper.size(); ++i) {
    EXPECT_EQ(baked.points[i], paper[i]) << "point " << i;
  }
}

}  // namespace
}  // namespace penumbra::reference
