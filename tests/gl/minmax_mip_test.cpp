// The min-max mip built on GL by the emitted minmax_init and minmax_reduce
// passes equals, texel for texel, the brute-force (min, max) of each node
// and the CPU reference's MinMaxMip, for a 1x1, an odd non-square, a
// non-power-of-two and a power-of-two map.
#include "penumbra/reference/minmax_mip.hpp"

#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "minmax_test_maps.hpp"

namespace penumbra::testing {
namespace {

struct MapSize {
  int width;
  int height;
};
using Case = std::tuple<Target, MapSize>;

class GlMinmaxMip : public ::testing::TestWithParam<Case> {};

TEST_P(GlMinmaxMip, EqualsBruteForceAndReference) {
  const auto& [target, size] = GetParam();
  const MinmaxText passes = default_minmax_passes(target);
  ASSERT_FALSE(passes.init.frag.empty());
  auto engine = make_gl_engine();
  ASSERT_NE(engine, nullptr);
  const FloatImage map = hashed_map(size.width, size.height);
  auto levels = engine->build_minmax(passes.view(), map, bare_map_params(map, 1, 1));
  ASSERT_TRUE(levels.ok()) << levels.error().to_string();

  const reference::MinMaxMip expected{reference::ShadowMapView(map)};
  ASSERT_EQ(static_cast<int>(levels->size()), expected.top_level());
  EXPECT_EQ(levels->back().width, 1);
  EXPECT_EQ(levels->back().height, 1);
  int wrong = 0;
  for (int l = 1; l <= expected.top_level(); ++l) {
    const FloatImage& level = (*levels)[static_cast<std::size_t>(l - 1)];
    ASSERT_EQ(level.channels, 2);
    ASSERT_EQ(level.width, expected.width(l)) << "level " << l;
    ASSERT_EQ(level.height, expected.height(l)) << "level " << l;
    for (int j = 0; j < level.height; ++j) {
      for (int i = 0; i < level.width; ++i) {
        const auto brute = brute_force_node(map, l, i, j);
        const reference::MinMax node = expected.node(l, i, j);
        const bool ok = level.at(i, j, 0) == brute[0] && level.at(i, j, 1) == brute[1] &&
                        node.min == brute[0] && node.max == brute[1];
        if (!ok && ++wrong <= 5) {
          ADD_FAILURE() << "level " << l << " node (" << i << ", " << j << "): GL ("
                        << level.at(i, j, 0) << ", " << level.at(i, j, 1) << "), brute force ("
                        << brute[0] << ", " << brute[1] << "), reference (" << node.min << ", "
                        << node.max << ")";
        }
      }
    }
  }
  EXPECT_EQ(wrong, 0);
}

std::string case_name(const ::testing::TestParamInfo<Case>& param_info) {
  const MapSize size = std::get<1>(param_info.param);
  return std::string(to_string(std::get<0>(param_info.param))) + "_" + std::to_string(size.width) +
         "x" + std::to_string(size.height);
}

INSTANTIATE_TEST_SUITE_P(Emitted, GlMinmaxMip,
                         ::testing::Combine(::testing::Values(Target::glsl330, Target::glsl450),
                                            ::testing::Values(MapSize{1, 1}, MapSize{3, 5},
                                                              MapSize{250, 190},
                                                              MapSize{256, 256})),
                         case_name);

}  // namespace
}  // namespace penumbra::testing
