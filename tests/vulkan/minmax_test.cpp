// The min-max mip on the device: built by minmax_init/minmax_reduce programs,
// equal bit for bit to the CPU mip for square, odd and power-of-two maps,
// bound whole as shadow_minmax; and the query pass's second output channel
// and GPU time. Every call runs under the validation layer.
#include <gtest/gtest.h>

#include <bit>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <random>
#include <string>
#include <vector>

#include "penumbra/reference/minmax_mip.hpp"
#include "penumbra/support/minmax_levels.hpp"
#include "test_programs.hpp"

namespace penumbra {
namespace {

const test::TestLight kLight;

// Normalized depth in [0, 1] with repeated values (flat runs) and distinct ones.
FloatImage random_map(int width, int height, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> depth(0.0f, 1.0f);
  FloatImage map(width, height, 1);
  for (float& d : map.data) d = (random() % 4 == 0) ? 0.5f : depth(random);
  return map;
}

bool same_bits(float a, float b) {
  return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}

// Whether `levels` (read_minmax) are the CPU mip of `depth`, bit for bit.
::testing::AssertionResult equals_cpu_mip(const std::vector<FloatImage>& levels,
                                          const FloatImage& depth) {
  const reference::MinMaxMip expected{reference::ShadowMapView(depth)};
  if (static_cast<int>(levels.size()) != expected.top_level()) {
    return ::testing::AssertionFailure()
           << levels.size() << " levels instead of " << expected.top_level();
  }
  for (int l = 1; l <= expected.top_level(); ++l) {
    const FloatImage& gpu = levels[static_cast<std::size_t>(l - 1)];
    if (gpu.width != expected.width(l) || gpu.height != expected.height(l) || gpu.channels != 2) {
      return ::testing::AssertionFailure()
             << "level " << l << " is " << gpu.width << "x" << gpu.height << "x" << gpu.channels
             << " instead of " << expected.width(l) << "x" << expected.height(l) << "x2";
    }
    for (int j = 0; j < gpu.height; ++j) {
      for (int i = 0; i < gpu.width; ++i) {
        const reference::MinMax node = expected.node(l, i, j);
        if (!same_bits(gpu.at(i, j, 0), node.min) || !same_bits(gpu.at(i, j, 1), node.max)) {
          return ::testing::AssertionFailure()
                 << "level " << l << " node " << i << ", " << j << ": (" << gpu.at(i, j, 0) << ", "
                 << gpu.at(i, j, 1) << ") instead of (" << node.min << ", " << node.max << ")";
        }
      }
    }
  }
  return ::testing::AssertionSuccess();
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

class MinmaxTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto engine = Engine::create({"", true}, [this](const Diagnostic& diagnostic) {
      const std::lock_guard lock(mutex_);
      if (diagnostic.where == "vulkan validation") validation_.push_back(diagnostic.message);
    });
    ASSERT_TRUE(engine) << engine.error().to_string();
    engine_ = std::move(*engine);
  }

  void TearDown() override {
    const std::lock_guard lock(mutex_);
    for (const std::string& message : validation_) ADD_FAILURE() << message;
  }

  // A map of `depth` with its mip built by the test programs.
  std::shared_ptr<ShadowMap> map_with_mip(const FloatImage& depth, MinmaxBuild* build = nullptr) {
    auto map = engine_->upload_shadow_map(depth);
    EXPECT_TRUE(map) << map.error().to_string();
    if (!map) return nullptr;
    auto built = engine_->build_minmax(
        **map, test::minmax_init_program(), test::minmax_reduce_program(),
        test::make_params(kLight, depth.width, depth.height, depth.width, depth.height));
    EXPECT_TRUE(built) << built.error().to_string();
    if (!built) return nullptr;
    if (build) *build = *built;
    return *map;
  }

  std::mutex mutex_;
  std::vector<std::string> validation_;
  std::unique_ptr<Engine> engine_;
};

class MinmaxBuildTest : public MinmaxTest,
                        public ::testing::WithParamInterface<std::array<int, 2>> {};

TEST_P(MinmaxBuildTest, EqualsTheCpuMipBitForBit) {
  const auto [width, height] = GetParam();
  const FloatImage depth = random_map(width, height, static_cast<unsigned>(width * 1000 + height));
  MinmaxBuild build;
  auto map = map_with_mip(depth, &build);
  ASSERT_NE(map, nullptr);
  const reference::MinMaxMip expected{reference::ShadowMapView(depth)};
  EXPECT_EQ(build.levels, expected.top_level());
  EXPECT_EQ(map->minmax_levels(), expected.top_level());
  EXPECT_EQ(minmax_top_level(width, height), expected.top_level());
  auto levels = engine_->read_minmax(*map);
  ASSERT_TRUE(levels) << levels.error().to_string();
  EXPECT_TRUE(equals_cpu_mip(*levels, depth));
  EXPECT_EQ(expected.width(expected.top_level()), 1);
  EXPECT_EQ(expected.height(expected.top_level()), 1);
}

INSTANTIATE_TEST_SUITE_P(Sizes, MinmaxBuildTest,
                         ::testing::Values(std::array{1, 1}, std::array{3, 5}, std::array{250, 190},
                                           std::array{256, 256}),
                         [](const auto& param_info) {
                           return std::to_string(param_info.param[0]) + "x" +
                                  std::to_string(param_info.param[1]);
                         });

// shadow_minmax is the whole chain with a sampler that reaches every level:
// hierarchy node (l, i, j) read at LOD l - 1 and uv (i + 0.5, j + 0.5) 2^(l - N),
// the chain being 2^(N - 1) square (docs/runtime.md). Its .x and .y come back
// as the visibility and the texel reads.
TEST_F(MinmaxTest, ShadowMinmaxReadsEveryLevelAndBothOutputChannelsComeBack) {
  const FloatImage depth = random_map(250, 190, 7);
  auto map = map_with_mip(depth);
  ASSERT_NE(map, nullptr);
  const reference::MinMaxMip expected{reference::ShadowMapView(depth)};
  const int top = expected.top_level();
  struct Node {
    int level, i, j;
  };
  std::vector<Node> nodes;
  for (int l = 1; l <= top; ++l) {
    nodes.push_back({l, 0, 0});
    nodes.push_back({l, expected.width(l) - 1, expected.height(l) - 1});
    nodes.push_back({l, expected.width(l) / 2, expected.height(l) / 3});
  }
  FloatImage receivers(static_cast<int>(nodes.size()), 1, 3);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const float scale = std::ldexp(1.0f, nodes[k].level - top);
    receivers.at(static_cast<int>(k), 0, 0) = (static_cast<float>(nodes[k].i) + 0.5f) * scale;
    receivers.at(static_cast<int>(k), 0, 1) = (static_cast<float>(nodes[k].j) + 0.5f) * scale;
    receivers.at(static_cast<int>(k), 0, 2) = static_cast<float>(nodes[k].level - 1);
  }
  auto output = engine_->run_query_output(
      test::minmax_probe_program(), *map, receivers,
      test::make_params(kLight, 250, 190, receivers.width, receivers.height));
  ASSERT_TRUE(output) << output.error().to_string();
  ASSERT_EQ(output->visibility.channels, 1);
  ASSERT_EQ(output->texel_reads.channels, 1);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const reference::MinMax node = expected.node(nodes[k].level, nodes[k].i, nodes[k].j);
    EXPECT_EQ(output->visibility.at(static_cast<int>(k), 0), node.min)
        << "level " << nodes[k].level << " node " << nodes[k].i << ", " << nodes[k].j;
    EXPECT_EQ(output->texel_reads.at(static_cast<int>(k), 0), node.max)
        << "level " << nodes[k].level << " node " << nodes[k].i << ", " << nodes[k].j;
  }
}

TEST_F(MinmaxTest, ShadowMinmaxOnAMapWithoutAMipIsABadInputNamingThePass) {
  auto map = engine_->upload_shadow_map(FloatImage(4, 4, 1, 0.5f));
  ASSERT_TRUE(map) << map.error().to_string();
  EXPECT_EQ((*map)->minmax_levels(), 0);
  auto output = engine_->run_query(test::minmax_probe_program(), **map, FloatImage(2, 2, 3),
                                   test::make_params(kLight, 4, 4, 2, 2));
  ASSERT_FALSE(output);
  EXPECT_EQ(output.error().kind, Error::Kind::bad_input);
  EXPECT_EQ(output.error().where, "query pass");
  EXPECT_NE(output.error().message.find("shadow_minmax"), std::string::npos)
      << output.error().message;
  EXPECT_NE(output.error().message.find("build_minmax"), std::string::npos)
      << output.error().message;
  auto levels = engine_->read_minmax(**map);
  ASSERT_FALSE(levels);
  EXPECT_EQ(levels.error().kind, Error::Kind::bad_input);
}

TEST_F(MinmaxTest, MinmaxSourceIsOnlyBoundInTheReducePasses) {
  auto map = engine_->upload_shadow_map(FloatImage(4, 4, 1, 0.5f));
  ASSERT_TRUE(map) << map.error().to_string();
  // The reduce program as the init pass: there is no level below the map.
  auto built =
      engine_->build_minmax(**map, test::minmax_reduce_program(), test::minmax_reduce_program(),
                            test::make_params(kLight, 4, 4, 4, 4));
  ASSERT_FALSE(built);
  EXPECT_EQ(built.error().where, "minmax_init pass");
  EXPECT_NE(built.error().message.find("minmax_source"), std::string::npos)
      << built.error().message;
}

// A rebuild replaces the mip: one built wrong (minmax_init writing (max,
// min)) and rebuilt with the right passes reads back as the CPU mip.
TEST_F(MinmaxTest, RebuildReplacesTheMip) {
  const FloatImage depth = random_map(37, 21, 11);
  auto map = engine_->upload_shadow_map(depth);
  ASSERT_TRUE(map) << map.error().to_string();
  const ParamBlock params = test::make_params(kLight, 37, 21, 37, 21);
  auto wrong = engine_->build_minmax(**map, test::minmax_init_program("minmax_init_swapped.frag"),
                                     test::minmax_reduce_program(), params);
  ASSERT_TRUE(wrong) << wrong.error().to_string();
  auto wrong_levels = engine_->read_minmax(**map);
  ASSERT_TRUE(wrong_levels) << wrong_levels.error().to_string();
  EXPECT_FALSE(equals_cpu_mip(*wrong_levels, depth));

  auto right = engine_->build_minmax(**map, test::minmax_init_program(),
                                     test::minmax_reduce_program(), params);
  ASSERT_TRUE(right) << right.error().to_string();
  EXPECT_EQ(right->levels, wrong->levels);
  EXPECT_EQ((*map)->minmax_levels(), minmax_top_level(37, 21));
  auto levels = engine_->read_minmax(**map);
  ASSERT_TRUE(levels) << levels.error().to_string();
  EXPECT_TRUE(equals_cpu_mip(*levels, depth));
}

// The min-max passes draw into R32G32_SFLOAT targets, (min, max).
TEST_F(MinmaxTest, MinmaxOutputNeedsBothChannelsOfItsTarget) {
  auto map = engine_->upload_shadow_map(FloatImage(4, 4, 1, 0.5f));
  ASSERT_TRUE(map) << map.error().to_string();
  PassProgram init = test::minmax_init_program();
  init.frag.iface.outputs[0].components = 1;
  auto built = engine_->build_minmax(**map, init, test::minmax_reduce_program(),
                                     test::make_params(kLight, 4, 4, 4, 4));
  ASSERT_FALSE(built);
  EXPECT_EQ(built.error().kind, Error::Kind::bad_input);
  EXPECT_EQ(built.error().where, "minmax_init pass");
  EXPECT_EQ(built.error().message,
            "fragment output 'minmax' has 1 component(s); the minmax_init pass's R32G32_SFLOAT "
            "target takes 2");
}

// minmax_init reads the map as shadow_depth only, as on GL.
TEST_F(MinmaxTest, MinmaxInitIsNotOfferedShadowCmp) {
  auto map = engine_->upload_shadow_map(FloatImage(4, 4, 1, 0.5f));
  ASSERT_TRUE(map) << map.error().to_string();
  PassProgram init = test::minmax_init_program();
  init.frag.iface.sampled_images.push_back({"shadow_cmp", 0, 2, true});
  const PassProgram compare = test::compare_program();
  for (const TextureBinding& texture : compare.reflection.frag.textures) {
    if (texture.name == "shadow_cmp") init.reflection.frag.textures.push_back(texture);
  }
  auto built = engine_->build_minmax(**map, init, test::minmax_reduce_program(),
                                     test::make_params(kLight, 4, 4, 4, 4));
  ASSERT_FALSE(built);
  EXPECT_EQ(built.error().kind, Error::Kind::bad_input);
  EXPECT_EQ(built.error().where, "minmax_init pass");
  EXPECT_EQ(built.error().message,
            "'shadow_cmp' has nothing to bind to in the minmax_init pass, which binds: "
            "ShadowParams, shadow_depth");
}

// lavapipe writes timestamps: the query and the mip build report GPU times,
// each within the wall-clock time of the call that waited for it.
TEST_F(MinmaxTest, TimestampsTimeTheQueryAndTheMipBuildOnLavapipe) {
  if (engine_->device_info().name.find("llvmpipe") == std::string::npos) {
    GTEST_SKIP() << "timestamps are optional on " << engine_->device_info().name;
  }
  MinmaxBuild build;
  auto build_start = std::chrono::steady_clock::now();
  auto map = map_with_mip(random_map(64, 64, 3), &build);
  const double build_wall_ms = milliseconds_since(build_start);
  ASSERT_NE(map, nullptr);
  ASSERT_TRUE(build.gpu_ms.has_value());
  EXPECT_GT(*build.gpu_ms, 0.0);
  EXPECT_LE(*build.gpu_ms, build_wall_ms);
  auto query_start = std::chrono::steady_clock::now();
  auto output = engine_->run_query_output(test::compare_program(), *map, FloatImage(32, 32, 3),
                                          test::make_params(kLight, 64, 64, 32, 32));
  const double query_wall_ms = milliseconds_since(query_start);
  ASSERT_TRUE(output) << output.error().to_string();
  ASSERT_TRUE(output->gpu_ms.has_value());
  EXPECT_GT(*output->gpu_ms, 0.0);
  EXPECT_LE(*output->gpu_ms, query_wall_ms);
}

}  // namespace
}  // namespace penumbra
