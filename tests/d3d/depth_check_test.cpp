// verify's depth check against a ray cast: a map one texel row or column
// off, what a wrong half pixel gives, fails it; the exact map passes.
#include <gtest/gtest.h>

#include "default_library.hpp"
#include "penumbra/reference/scene.hpp"
#include "scene_fixture.hpp"

namespace penumbra::testing {
namespace {

// `map` moved by (dx, dy) texels, the vacated edge repeating its neighbour.
FloatImage shifted(const FloatImage& map, int dx, int dy) {
  FloatImage out(map.width, map.height, 1);
  for (int j = 0; j < map.height; ++j) {
    for (int i = 0; i < map.width; ++i) {
      out.at(i, j) =
          map.at(std::clamp(i - dx, 0, map.width - 1), std::clamp(j - dy, 0, map.height - 1));
    }
  }
  return out;
}

class DepthCheckTest : public ::testing::TestWithParam<reference::Scene> {};

TEST_P(DepthCheckTest, TheRayCastPassesAndAShiftByOneTexelFails) {
  const reference::Scene& scene = GetParam();
  const FloatImage exact =
      reference::ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z);
  const DepthCheck same = check_depth(scene, Target::hlsl_dx9, exact, "d3d9");
  EXPECT_TRUE(same.pass) << same.mismatched << " of " << same.texels;
  // Nearly every texel is checked: only those within 1/8 texel of an edge are not.
  EXPECT_GT(same.texels, exact.pixel_count() * 95 / 100);
  for (const auto& [dx, dy] : {std::pair{0, 1}, std::pair{0, -1}, std::pair{1, 0}}) {
    const DepthCheck off = check_depth(scene, Target::hlsl_dx9, shifted(exact, dx, dy), "d3d9");
    EXPECT_FALSE(off.pass) << "shifted by (" << dx << ", " << dy << ")";
    // Every edge the shift crosses: far more than rounding could explain.
    EXPECT_GT(off.mismatched, 20u) << "shifted by (" << dx << ", " << dy << ")";
  }
}

INSTANTIATE_TEST_SUITE_P(BuiltinScenes, DepthCheckTest,
                         ::testing::ValuesIn(reference::builtin_scenes()),
                         [](const auto& param_info) { return test_name(param_info.param.name); });

}  // namespace
}  // namespace penumbra::testing
