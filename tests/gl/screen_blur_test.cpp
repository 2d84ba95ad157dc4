// screen_blur's chain on GL (query, blur_h, blur_v, composite), checked as
// penumbra verify checks it on Vulkan: the factor against the CPU reference,
// each blur pass against the CPU's blur of the GL pass's own input, and the
// composite against the CPU's composite of the GL blurred factor, on every
// built-in scene.
#include "penumbra/reference/screen_blur.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "default_library.hpp"
#include "gl_fixture.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/reference/compare.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/runtime/pass_driver.hpp"
#include "screen_chain.hpp"

namespace penumbra::testing {
namespace {

// As query_test.cpp: llvmpipe samples as lavapipe, with 8 sub-texel bits.
constexpr reference::SamplingPrecision kLlvmpipePrecision{8};

// Largest |gpu - cpu| over every value; infinity for another shape or a NaN.
double max_abs_error(const FloatImage& gpu, const FloatImage& cpu) {
  if (gpu.width != cpu.width || gpu.height != cpu.height || gpu.channels != cpu.channels) {
    return INFINITY;
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < gpu.data.size(); ++i) {
    const double error = std::abs(double(gpu.data[i]) - double(cpu.data[i]));
    worst = std::isnan(error) ? INFINITY : std::max(worst, error);
  }
  return worst;
}

using Case = std::tuple<std::string, Target>;

class GlScreenBlur : public ::testing::TestWithParam<Case> {};

TEST_P(GlScreenBlur, EveryPassMatchesTheReferenceOnEveryScene) {
  const auto& [name, target] = GetParam();
  auto variant = find_default_variant(name);
  ASSERT_NE(variant, nullptr);
  // The technique's pass list from the model, as verify's GL path runs it.
  const std::vector<PassKind> passes = runtime::select_passes(
      describe(variant->technique).passes, /*draw_depth=*/false, /*deferred=*/false);
  std::map<PassKind, PassText> texts;
  for (PassKind pass : passes) {
    auto text = emitted_pass(*variant, target, pass);
    ASSERT_TRUE(text.ok()) << text.error().to_string();
    texts.emplace(pass, std::move(*text));
  }
  std::map<PassKind, GlPass> programs;
  for (const auto& [pass, text] : texts) programs.emplace(pass, text.view());
  auto engine = make_gl_engine();
  ASSERT_NE(engine, nullptr);
  const bool depth_aware = variant->keys.depth_aware.value_or(false);
  for (const reference::Scene& scene : reference::builtin_scenes()) {
    const SceneInputs inputs = scene_inputs(scene);
    const FloatImage colour =
        reference::scene_colour(inputs.receivers.width, inputs.receivers.height);
    auto outputs = engine->run_passes(passes, programs, inputs.normalized_depth,
                                      {.receivers = &inputs.receivers, .scene_colour = &colour},
                                      inputs.params);
    ASSERT_TRUE(outputs.ok()) << scene.name << ": " << outputs.error().to_string();
    auto read = screen_chain(*outputs);
    ASSERT_TRUE(read.ok()) << scene.name << ": " << read.error().to_string();
    const ScreenChain& chain = *read;

    auto expected = reference::evaluate_image(*variant, inputs.linear_depth, scene.light,
                                              inputs.receivers, kLlvmpipePrecision);
    ASSERT_TRUE(expected.ok()) << expected.error().to_string();
    auto factor = reference::compare(chain.factor, expected->visibility, expected->ambiguous,
                                     reference::tolerance(variant->technique, kLlvmpipePrecision));
    ASSERT_TRUE(factor.ok()) << factor.error().to_string();
    EXPECT_TRUE(factor->pass) << scene.name << ": factor max error " << factor->max_abs_error;
    EXPECT_GT(factor->compared, factor->pixels * 9 / 10) << scene.name;

    const FloatImage* receivers = depth_aware ? &inputs.receivers : nullptr;
    const FloatImage blurred_h =
        reference::blur_horizontal(chain.factor, variant->blur_weights, receivers);
    EXPECT_LE(max_abs_error(chain.blurred_h, blurred_h), reference::kBlurTolerance) << scene.name;
    const FloatImage blurred_v =
        reference::blur_vertical(chain.blurred_h, variant->blur_weights, receivers);
    EXPECT_LE(max_abs_error(chain.blurred, blurred_v), reference::kBlurTolerance) << scene.name;
    EXPECT_LE(max_abs_error(chain.blurred,
                            reference::screen_blur(*variant, chain.factor, inputs.receivers)),
              reference::kBlurTolerance)
        << scene.name;
    // The blur does blur: a penumbra's factor changes.
    EXPECT_GT(max_abs_error(chain.blurred, chain.factor), 1e-3) << scene.name;
    EXPECT_LE(max_abs_error(chain.composite, reference::composite(colour, chain.blurred)),
              reference::kCompositeTolerance)
        << scene.name;
  }
}

std::string case_name(const ::testing::TestParamInfo<Case>& param_info) {
  return std::get<0>(param_info.param) + "_" +
         std::string(to_string(std::get<1>(param_info.param)));
}

INSTANTIATE_TEST_SUITE_P(Emitted, GlScreenBlur,
                         ::testing::Combine(::testing::Values("screen_blur_r2", "screen_blur_r8",
                                                              "screen_blur_r4_depth_aware"),
                                            ::testing::Values(Target::glsl330, Target::glsl450)),
                         case_name);

}  // namespace
}  // namespace penumbra::testing
