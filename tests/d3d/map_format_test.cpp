// Engines' D24 and D16 shadow maps on Wine's Direct3D 10 and 11: each
// runtime draws the map into an R24G8_TYPELESS or R16_TYPELESS texture
// through its D24_UNORM_S8_UINT or D16_UNORM depth view, and the query,
// function form and deferred pass read it through its unorm view, against
// the CPU reference on the codes the runtime stored.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "default_library.hpp"
#include "hlsl_compiler.hpp"
#include "penumbra/verify/verify.hpp"

namespace penumbra::testing {
namespace {

const std::vector<Target> kTargets = {Target::hlsl_dx10, Target::hlsl_dx11};

// A comparison-filtered technique, PCSS's blocker depths, and a min-max
// technique, forward, reversed-Z and orthographic.
const char* const kVariants[] = {"pcf_grid_k3_perspective",
                                 "pcss_b16_p16_poisson_perspective_reversed",
                                 "pcss_b16_p16_poisson_orthographic", "backprojection_perspective"};

class Direct3DMapFormat : public ::testing::TestWithParam<DepthFormat> {};

TEST_P(Direct3DMapFormat, EveryCheckPassesOnTheRuntimesUnormMap) {
  const DepthFormat format = GetParam();
  auto compiler = recorded_hlsl_compiler();
  ASSERT_TRUE(compiler) << compiler.error().to_string();
  std::vector<Variant> variants;
  for (const char* name : kVariants) {
    const Variant* variant = find_default_variant(name);
    ASSERT_NE(variant, nullptr) << name;
    variants.push_back(*variant);
  }
  auto built =
      TemporaryLibrary::build(variants, kTargets, {.jobs = 2, .hlsl = {.compiler = *compiler}});
  ASSERT_TRUE(built) << built.error().to_string();
  auto engine = Engine::create({.device = "", .validation = false}, ignore_diagnostics());
  ASSERT_TRUE(engine) << engine.error().to_string();
  auto report = verify_library((*built)->library(), **engine,
                               {.variants = {},
                                .targets = kTargets,
                                .skipped = {"gl"},
                                .paths = {"d3d10", "d3d11"},
                                .map_format = format,
                                // compiles the engine's own HLSL around each function form
                                .bytecode = {.compiler = *compiler}},
                               ignore_diagnostics());
  ASSERT_TRUE(report) << report.error().to_string();

  // Each runtime draws its own unorm maps, which must match the ray cast.
  std::set<std::string> drawn;
  for (const DepthCheck& depth : report->depth_checks) {
    EXPECT_TRUE(depth.pass) << "depth pass of " << to_string(depth.target) << " on "
                            << depth.backend << ", " << depth.scene << ": " << depth.mismatched
                            << " of " << depth.texels << " texels off";
    EXPECT_EQ(depth.map_format, format) << depth.backend << " " << depth.scene;
    drawn.insert(depth.backend);
  }
  EXPECT_EQ(drawn, (std::set<std::string>{"vulkan", "d3d10", "d3d11"}));

  std::size_t runs = 0;
  for (const VariantRun& variant : report->variants) {
    for (const TargetRun& run : variant.runs) {
      const std::string label =
          variant.name + " [" + std::string(to_string(run.target)) + " on " + run.backend + "]";
      ASSERT_TRUE(run.executed) << label << ": " << run.not_executed;
      ASSERT_TRUE(run.error.empty()) << label << ": " << run.error;
      ++runs;
      for (const SceneRun& scene : run.scenes) {
        const auto& c = scene.comparison;
        EXPECT_TRUE(scene.pass()) << label << " on " << scene.scene << ": max error "
                                  << c.max_abs_error << " (tolerance " << c.tolerance << "), "
                                  << c.over_tolerance << " pixels over, " << c.ambiguous
                                  << " ambiguous of " << c.pixels;
        // A unorm step widens the ties, not so far that nothing is compared.
        EXPECT_GT(c.compared, c.pixels * 9 / 10) << label << " " << scene.scene;
      }
    }
  }
  EXPECT_EQ(runs, std::size(kVariants) * kTargets.size());

  std::set<std::string> forms;
  for (const auto& [form, checks] : {std::pair{"function form", &report->function_checks},
                                     std::pair{"deferred mask", &report->deferred_checks}}) {
    for (const EngineFormCheck& c : *checks) {
      const std::string label = std::string(form) + " " + c.variant + ", " +
                                std::string(to_string(c.target)) + " on " + c.backend;
      EXPECT_TRUE(c.pass) << label << ": " << c.error << " max error " << c.comparison.max_abs_error
                          << ", " << c.comparison.over_tolerance << " pixels over";
      EXPECT_EQ(c.map_format, format) << label;
      forms.insert(std::string(form) + " on " + c.backend);
    }
  }
  EXPECT_EQ(forms, (std::set<std::string>{"function form on d3d10", "function form on d3d11",
                                          "deferred mask on d3d10", "deferred mask on d3d11"}));
}

INSTANTIATE_TEST_SUITE_P(Unorm, Direct3DMapFormat,
                         ::testing::Values(DepthFormat::d24_unorm, DepthFormat::d16_unorm),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

}  // namespace
}  // namespace penumbra::testing
