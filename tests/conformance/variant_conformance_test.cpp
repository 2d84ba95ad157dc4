// Every variant of permutations/default.json, executed on the Vulkan device
// (lavapipe) over the project's scenes and checked against the CPU reference.
#include <gtest/gtest.h>

#include "library_fixture.hpp"
#include "penumbra/runtime/verify.hpp"

namespace penumbra::testing {
namespace {

class VariantConformance : public ::testing::TestWithParam<std::string> {};

TEST_P(VariantConformance, SpirvMatchesReferenceOnEveryScene) {
  auto lib = build_default_variant(GetParam(), /*with_engine=*/true);
  ASSERT_NE(lib, nullptr);
  auto report =
      verify_library(lib->library, *lib->engine, {.variants = {GetParam()}}, ignore_diagnostics());
  ASSERT_TRUE(report.ok()) << report.error().to_string();
  for (const DepthCheck& depth : report->depth_checks) {
    EXPECT_TRUE(depth.pass) << "depth pass on " << depth.scene << ": " << depth.mismatched << " of "
                            << depth.texels << " texels off";
  }
  ASSERT_EQ(report->variants.size(), 1u);
  bool spirv_ran = false;
  for (const TargetRun& run : report->variants[0].targets) {
    if (!run.executed) continue;
    spirv_ran = spirv_ran || run.target == Target::spirv;
    ASSERT_FALSE(run.scenes.empty());
    for (const SceneRun& scene : run.scenes) {
      const auto& c = scene.comparison;
      EXPECT_TRUE(c.pass) << to_string(run.target) << " on " << scene.scene << ": max error "
                          << c.max_abs_error << " (tolerance " << c.tolerance << "), "
                          << c.over_tolerance << " pixels over, " << c.ambiguous << " ambiguous of "
                          << c.pixels;
      // A scene that leaves almost everything ambiguous would check nothing.
      EXPECT_GT(c.compared, c.pixels * 9 / 10) << scene.scene;
    }
  }
  EXPECT_TRUE(spirv_ran);
}

INSTANTIATE_TEST_SUITE_P(Default, VariantConformance, ::testing::ValuesIn(default_variant_names()),
                         [](const auto& param_info) { return test_name(param_info.param); });

}  // namespace
}  // namespace penumbra::testing
