// The text targets' paths: a default variant's emitted text for each
// target, compiled by glslang and bound by the target's reflection record,
// produces what the SPIR-V path produces on the same inputs. Runs under the
// validation layer, whose errors fail the call.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "default_library.hpp"
#include "test_programs.hpp"
#include "text_programs.hpp"

namespace penumbra {
namespace {

constexpr int kSize = 16;
const test::TestLight kLight;  // n = 9.5, Fw = 3.75, depth_scale = 1/32

// Casters asymmetric in u and v (a flip shows), overlapping, and one
// triangle whose slanted edges cross texels at odd places.
std::vector<std::array<float, 3>> scene() {
  std::vector<std::array<float, 3>> triangles;
  test::add_caster_quad(triangles, kLight, 0.5f, 1.25f, 0.0625f, 0.375f, 12.0f);
  test::add_caster_quad(triangles, kLight, 0.25f, 0.75f, 0.25f, 0.75f, 24.0f);
  triangles.push_back({-0.61f, 0.17f, 15.3f});
  triangles.push_back({-0.13f, 0.93f, 15.7f});
  triangles.push_back({-1.07f, 1.21f, 16.9f});
  return triangles;
}

// Receivers at off-centre points between z = 12 and z = 24 (even rows) and
// behind everything (odd rows), so comparisons take every value in [0, 1].
FloatImage receivers() {
  constexpr int kCount = 24;
  FloatImage image(kCount, kCount, 3);
  for (int j = 0; j < kCount; ++j) {
    for (int i = 0; i < kCount; ++i) {
      image.at(i, j, 0) = 0.02f + 0.96f * static_cast<float>(i) / (kCount - 1);
      image.at(i, j, 1) = 0.03f + 0.94f * static_cast<float>(j) / (kCount - 1);
      image.at(i, j, 2) = j % 2 == 0 ? 18.0f : 30.0f;
    }
  }
  return image;
}

class TextPathTest : public ::testing::TestWithParam<Target> {
 protected:
  void SetUp() override {
    engine_ = test::make_engine(/*validation=*/true);
    ASSERT_NE(engine_, nullptr);
  }

  std::shared_ptr<ShadowMap> render(const PassProgram& program) {
    auto map = engine_->render_depth(program, scene(), kSize, kSize, params_);
    EXPECT_TRUE(map) << map.error().to_string();
    return map ? *map : nullptr;
  }

  std::unique_ptr<Engine> engine_;
  ParamBlock params_ = test::make_params(kLight, kSize, kSize, 24, 24);
};

TEST_P(TextPathTest, DepthPassWritesTheSameTexels) {
  const auto expected_map = render(test::text_program("hard", PassKind::depth, Target::spirv));
  const auto map = render(test::text_program("hard", PassKind::depth, GetParam()));
  ASSERT_TRUE(expected_map && map);
  auto expected = engine_->read_shadow_map(*expected_map);
  auto depth = engine_->read_shadow_map(*map);
  ASSERT_TRUE(expected && depth);
  int covered = 0;
  for (int j = 0; j < kSize; ++j) {
    for (int i = 0; i < kSize; ++i) {
      EXPECT_EQ(depth->at(i, j), expected->at(i, j)) << "texel " << i << ", " << j;
      covered += expected->at(i, j) < 1.0f;
    }
  }
  EXPECT_GT(covered, kSize * kSize / 4);
  // The depth images agree too: the same comparisons through each.
  auto expected_lit =
      engine_->run_query(test::compare_program(), *expected_map, receivers(), params_);
  auto lit = engine_->run_query(test::compare_program(), *map, receivers(), params_);
  ASSERT_TRUE(expected_lit && lit);
  EXPECT_EQ(lit->data, expected_lit->data);
}

TEST_P(TextPathTest, QueryPassComparesAsTheSpirvPath) {
  const auto map = render(test::depth_program());
  ASSERT_TRUE(map);
  auto expected =
      engine_->run_query(test::text_program("pcf_grid_k3", PassKind::query, Target::spirv), *map,
                         receivers(), params_);
  ASSERT_TRUE(expected) << expected.error().to_string();
  auto visibility = engine_->run_query(
      test::text_program("pcf_grid_k3", PassKind::query, GetParam()), *map, receivers(), params_);
  ASSERT_TRUE(visibility) << visibility.error().to_string();
  ASSERT_EQ(visibility->data.size(), expected->data.size());
  int shadowed = 0;
  int lit = 0;
  int partial = 0;
  for (std::size_t k = 0; k < expected->data.size(); ++k) {
    EXPECT_NEAR(visibility->data[k], expected->data[k], 2.0 / 256) << "receiver " << k;
    const float value = expected->data[k];
    ++(value == 0.0f ? shadowed : value == 1.0f ? lit : partial);
  }
  EXPECT_GT(shadowed, 20);
  EXPECT_GT(lit, 20);
  EXPECT_GT(partial, 20);
}

INSTANTIATE_TEST_SUITE_P(Targets, TextPathTest, ::testing::ValuesIn(testing::text_targets()),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

}  // namespace
}  // namespace penumbra
