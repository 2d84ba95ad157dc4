// Query passes that read shadow_minmax: a probe that reads every node of
// every level where docs/gl.md says it lies, and the emitted minmax_pcf
// passes on every built-in scene against a brute-force count of the
// occluding texels (bit-exact) and the reference traversal's node reads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "default_library.hpp"
#include "minmax_test_maps.hpp"
#include "penumbra/reference/minmax_mip.hpp"
#include "penumbra/reference/minmax_pcf.hpp"

namespace penumbra::testing {
namespace {

// A query pass that returns the mip texel at receiver (u, v) of LOD z_r.
std::string probe_vert(Target target) {
  const bool v450 = target == Target::glsl450;
  return std::string(v450 ? "#version 450\nlayout(location = 0) " : "#version 330\n") +
         "in vec2 position;\n" + (v450 ? "layout(location = 0) " : "") +
         "out vec2 screen_uv;\n"
         "void main() {\n"
         "  screen_uv = position * 0.5 + 0.5;\n"
         "  gl_Position = vec4(position, 0.0, 1.0);\n"
         "}\n";
}

std::string probe_frag(Target target) {
  const bool v450 = target == Target::glsl450;
  return std::string(v450 ? "#version 450\n" : "#version 330\n") +
         (v450 ? "layout(binding = 3) " : "") + "uniform sampler2D receivers;\n" +
         (v450 ? "layout(binding = 4) " : "") + "uniform sampler2D shadow_minmax;\n" +
         (v450 ? "layout(location = 0) " : "") + "in vec2 screen_uv;\n" +
         (v450 ? "layout(location = 0) " : "") +
         "out vec4 visibility;\n"
         "void main() {\n"
         "  vec3 query = textureLod(receivers, screen_uv, 0.0).xyz;\n"
         "  visibility = vec4(textureLod(shadow_minmax, query.xy, query.z).rg, 0.0, 0.0);\n"
         "}\n";
}

struct Node {
  int level, i, j;
};

class GlMinmaxProbe : public ::testing::TestWithParam<Target> {};

// Hierarchy node (l, i, j) lies at texel (i, j) of mip level l - 1, whose
// level 0 is 2^(N-1) square: uv (i + 0.5, j + 0.5) / 2^(N-l), LOD l - 1.
TEST_P(GlMinmaxProbe, EveryNodeAtItsTexelAndLevel) {
  const Target target = GetParam();
  const MinmaxText passes = default_minmax_passes(target);
  ASSERT_FALSE(passes.init.frag.empty());
  auto engine = make_gl_engine();
  ASSERT_NE(engine, nullptr);
  const FloatImage map = hashed_map(250, 190);
  const int top = 8;  // ceil(log2(250))
  std::vector<Node> nodes;
  for (int l = 1; l <= top; ++l) {
    for (int j = 0; j < (190 + (1 << l) - 1) >> l; ++j) {
      for (int i = 0; i < (250 + (1 << l) - 1) >> l; ++i) nodes.push_back({l, i, j});
    }
  }
  const int columns = 128;
  const int rows = static_cast<int>((nodes.size() + columns - 1) / columns);
  FloatImage receivers(columns, rows, 3);
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const Node& node = nodes[n];
    const float side = static_cast<float>(1 << (top - node.level));
    float* pixel = &receivers.data[3 * n];
    pixel[0] = (static_cast<float>(node.i) + 0.5f) / side;
    pixel[1] = (static_cast<float>(node.j) + 0.5f) / side;
    pixel[2] = static_cast<float>(node.level - 1);
  }
  // Bound by minmax_pcf_k8's query reflection, whose names the probe's are
  // a subset of.
  auto variant = find_default_variant("minmax_pcf_k8");
  ASSERT_NE(variant, nullptr);
  auto query = emitted_pass(*variant, target, PassKind::query);
  ASSERT_TRUE(query.ok()) << query.error().to_string();
  const PassText probe{probe_vert(target), probe_frag(target), query->reflection};
  auto output = engine->run_query({probe.view(), passes.view()}, map, receivers,
                                  bare_map_params(map, columns, rows));
  ASSERT_TRUE(output.ok()) << output.error().to_string();
  int wrong = 0;
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const Node& node = nodes[n];
    const auto expected = brute_force_node(map, node.level, node.i, node.j);
    const float min = output->visibility.data[n];
    const float max = output->texel_reads.data[n];
    if ((min != expected[0] || max != expected[1]) && ++wrong <= 5) {
      ADD_FAILURE() << "level " << node.level << " node (" << node.i << ", " << node.j
                    << "): read (" << min << ", " << max << "), expected (" << expected[0] << ", "
                    << expected[1] << ")";
    }
  }
  EXPECT_EQ(wrong, 0) << "of " << nodes.size() << " nodes";
}

INSTANTIATE_TEST_SUITE_P(HandWritten, GlMinmaxProbe,
                         ::testing::Values(Target::glsl330, Target::glsl450),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

using Case = std::tuple<std::string, Target>;

class GlMinmaxPcf : public ::testing::TestWithParam<Case> {};

// 1 - C / K^2 with C counted texel by texel, in the shader's float
// arithmetic: window from floor(u W), reference (z_r - bias) * depth_scale.
float brute_force_visibility(const FloatImage& map, float u, float v, float reference, int kernel) {
  const int x0 = static_cast<int>(std::floor(u * static_cast<float>(map.width))) - kernel / 2;
  const int y0 = static_cast<int>(std::floor(v * static_cast<float>(map.height))) - kernel / 2;
  int count = 0;
  for (int y = std::max(y0, 0); y < std::min(y0 + kernel, map.height); ++y) {
    for (int x = std::max(x0, 0); x < std::min(x0 + kernel, map.width); ++x) {
      if (map.at(x, y) < reference) ++count;
    }
  }
  return 1.0f - static_cast<float>(count) / static_cast<float>(kernel * kernel);
}

TEST_P(GlMinmaxPcf, BitExactOnEveryScene) {
  const auto& [name, target] = GetParam();
  auto variant = find_default_variant(name);
  ASSERT_NE(variant, nullptr);
  ASSERT_TRUE(variant->keys.kernel.has_value());
  const int kernel = *variant->keys.kernel;
  auto query = emitted_pass(*variant, target, PassKind::query);
  ASSERT_TRUE(query.ok()) << query.error().to_string();
  auto minmax = emitted_minmax(*variant, target);
  ASSERT_TRUE(minmax.ok()) << minmax.error().to_string();
  auto engine = make_gl_engine();
  ASSERT_NE(engine, nullptr);
  for (const reference::Scene& scene : reference::builtin_scenes()) {
    const SceneInputs inputs = scene_inputs(scene);
    auto gpu = engine->run_query({query->view(), minmax->view()}, inputs.normalized_depth,
                                 inputs.receivers, inputs.params);
    ASSERT_TRUE(gpu.ok()) << scene.name << ": " << gpu.error().to_string();
    const auto sampling = inputs.params.at("sampling");  // bias, depth_scale in .y, .z
    const reference::MinMaxMip mip{reference::ShadowMapView(inputs.linear_depth)};
    int wrong_visibility = 0;
    int wrong_reads = 0;
    for (int j = 0; j < inputs.receivers.height; ++j) {
      for (int i = 0; i < inputs.receivers.width; ++i) {
        const float u = inputs.receivers.at(i, j, 0);
        const float v = inputs.receivers.at(i, j, 1);
        const float reference = (inputs.receivers.at(i, j, 2) - sampling[1]) * sampling[2];
        const float expected =
            brute_force_visibility(inputs.normalized_depth, u, v, reference, kernel);
        const float got = gpu->visibility.at(i, j);
        if (got != expected && ++wrong_visibility <= 5) {
          ADD_FAILURE() << scene.name << " pixel (" << i << ", " << j << "): " << got
                        << ", brute force " << expected;
        }
        const reference::TexelRect window = reference::minmax_pcf_window(
            reference::ShadowMapView(inputs.linear_depth), u, v, kernel);
        const auto counted = reference::count_occluders(mip, window, reference / sampling[2]);
        if (gpu->texel_reads.at(i, j) != static_cast<float>(counted.reads) && ++wrong_reads <= 5) {
          ADD_FAILURE() << scene.name << " pixel (" << i << ", " << j
                        << "): " << gpu->texel_reads.at(i, j)
                        << " texels read, the reference traversal " << counted.reads;
        }
      }
    }
    EXPECT_EQ(wrong_visibility, 0) << scene.name;
    EXPECT_EQ(wrong_reads, 0) << scene.name;
  }
}

std::string case_name(const ::testing::TestParamInfo<Case>& param_info) {
  return std::get<0>(param_info.param) + "_" +
         std::string(to_string(std::get<1>(param_info.param)));
}

INSTANTIATE_TEST_SUITE_P(Emitted, GlMinmaxPcf,
                         ::testing::Combine(::testing::Values("minmax_pcf_k8", "minmax_pcf_k64"),
                                            ::testing::Values(Target::glsl330, Target::glsl450)),
                         case_name);

}  // namespace
}  // namespace penumbra::testing
