// Real emitted glsl330 and glsl450 query passes, compiled by Mesa's GL
// compiler and run on llvmpipe, against the CPU reference on every built-in
// scene, with the tolerance penumbra verify uses on lavapipe.
#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <tuple>

#include "default_library.hpp"
#include "gl_fixture.hpp"
#include "penumbra/reference/compare.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::testing {
namespace {

// llvmpipe samples with Mesa's gallivm code, as lavapipe does; lavapipe
// reports 8 sub-texel bits and GL has no query for them.
constexpr reference::SamplingPrecision kLlvmpipePrecision{8};

using Case = std::tuple<std::string, Target>;

class GlQueryConformance : public ::testing::TestWithParam<Case> {};

TEST_P(GlQueryConformance, MatchesReferenceOnEveryScene) {
  const auto& [name, target] = GetParam();
  auto variant = find_default_variant(name);
  ASSERT_NE(variant, nullptr);
  auto text = emitted_pass(*variant, target, PassKind::query);
  ASSERT_TRUE(text.ok()) << text.error().to_string();
  auto engine = make_gl_engine();
  ASSERT_NE(engine, nullptr);
  const double tolerance = reference::tolerance(variant->technique, kLlvmpipePrecision);
  for (const reference::Scene& scene : reference::builtin_scenes()) {
    const SceneInputs inputs = scene_inputs(scene);
    auto gpu =
        engine->run_query({text->view()}, inputs.normalized_depth, inputs.receivers, inputs.params);
    ASSERT_TRUE(gpu.ok()) << gpu.error().to_string();
    auto expected = reference::evaluate_image(*variant, inputs.linear_depth, scene.light,
                                              inputs.receivers, kLlvmpipePrecision);
    ASSERT_TRUE(expected.ok()) << expected.error().to_string();
    auto c =
        reference::compare(gpu->visibility, expected->visibility, expected->ambiguous, tolerance);
    ASSERT_TRUE(c.ok()) << c.error().to_string();
    std::cout << name << " " << to_string(target) << " on " << scene.name << ": max error "
              << c->max_abs_error << ", mean " << c->mean_abs_error << " (tolerance "
              << c->tolerance << "), " << c->ambiguous << " of " << c->pixels << " ambiguous\n";
    EXPECT_TRUE(c->pass) << scene.name << ": max error " << c->max_abs_error << ", "
                         << c->over_tolerance << " pixels over " << c->tolerance << ", "
                         << c->ambiguous << " ambiguous of " << c->pixels;
    // A scene that leaves almost everything ambiguous would check nothing.
    EXPECT_GT(c->compared, c->pixels * 9 / 10) << scene.name;
  }
}

std::string case_name(const ::testing::TestParamInfo<Case>& param_info) {
  return std::get<0>(param_info.param) + "_" +
         std::string(to_string(std::get<1>(param_info.param)));
}

INSTANTIATE_TEST_SUITE_P(Emitted, GlQueryConformance,
                         ::testing::Combine(::testing::Values("hard", "pcf_grid_k3",
                                                              "pcf_poisson_p16_whitepaper16",
                                                              "pcss_b16_p16_whitepaper16"),
                                            ::testing::Values(Target::glsl330, Target::glsl450)),
                         case_name);

}  // namespace
}  // namespace penumbra::testing
