// Engines' D24 and D16 shadow maps (VerifyOptions::map_format): each
// encoded variant's maps drawn into a unorm depth image by its own depth
// pass, read by its query, function form and deferred pass on Vulkan and
// through the OpenGL driver, against the CPU reference on the stored codes.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "default_library.hpp"
#include "penumbra/verify/verify.hpp"
#include "penumbra/vulkan/engine.hpp"
#include "validation_messages.hpp"

namespace penumbra::testing {
namespace {

struct MapFormatCase {
  std::string variant;
  DepthFormat format;
};

// A comparison-filtered technique and the one that linearizes blocker
// depths, forward, reversed-Z and orthographic.
const MapFormatCase kCases[] = {
    {"pcf_grid_k3_perspective", DepthFormat::d16_unorm},
    {"pcf_grid_k3_perspective", DepthFormat::d24_unorm},
    {"pcss_b16_p16_poisson_perspective_reversed", DepthFormat::d16_unorm},
    {"pcss_b16_p16_poisson_perspective_reversed", DepthFormat::d24_unorm},
    {"pcss_b16_p16_poisson_orthographic", DepthFormat::d16_unorm},
};

class MapFormatConformance : public ::testing::TestWithParam<MapFormatCase> {};

TEST_P(MapFormatConformance, EveryCheckPassesOnTheUnormMap) {
  const MapFormatCase& param = GetParam();
  auto built = build_default_variant(param.variant);
  ASSERT_TRUE(built) << built.error().to_string();
  auto engine = Engine::create({.device = "", .validation = true}, fail_on_validation_messages());
  ASSERT_TRUE(engine) << engine.error().to_string();
  auto report = verify_library((*built)->library(), **engine,
                               {.variants = {param.variant},
                                .targets = {},
                                .skipped = {"d3d9", "d3d10", "d3d11"},
                                .paths = {"vulkan", "gl"},
                                .map_format = param.format},
                               ignore_diagnostics());
  ASSERT_TRUE(report.ok()) << report.error().to_string();

  std::set<Target> unorm_maps;
  for (const DepthCheck& depth : report->depth_checks) {
    EXPECT_TRUE(depth.pass) << "depth pass of " << to_string(depth.target) << " on " << depth.scene
                            << ": " << depth.mismatched << " of " << depth.texels
                            << " texels off, max error " << depth.max_abs_error;
    // hlsl_dx9 reads its R32F target; every other target the unorm image.
    EXPECT_EQ(depth.map_format,
              depth.target == Target::hlsl_dx9 ? DepthFormat::d32_float : param.format)
        << to_string(depth.target);
    if (depth.map_format == param.format) unorm_maps.insert(depth.target);
  }
  EXPECT_GE(unorm_maps.size(), 5u);

  ASSERT_EQ(report->variants.size(), 1u);
  std::set<std::string> paths;
  for (const TargetRun& run : report->variants[0].runs) {
    const std::string label = std::string(to_string(run.target)) + " on " + run.backend;
    if (!run.executed) continue;
    ASSERT_TRUE(run.error.empty()) << label << ": " << run.error;
    paths.insert(run.backend);
    for (const SceneRun& scene : run.scenes) {
      const auto& c = scene.comparison;
      EXPECT_TRUE(c.pass) << label << " on " << scene.scene << ": max error " << c.max_abs_error
                          << " (tolerance " << c.tolerance << "), " << c.over_tolerance
                          << " pixels over, " << c.ambiguous << " ambiguous of " << c.pixels;
      // A unorm step widens the ties, not so far that nothing is compared.
      EXPECT_GT(c.compared, c.pixels * 9 / 10) << label << " " << scene.scene;
    }
  }
  EXPECT_TRUE(paths.contains("vulkan"));
  EXPECT_TRUE(paths.contains("gl"));

  std::set<std::string> forms;
  for (const auto& [form, checks] : {std::pair{"function form", &report->function_checks},
                                     std::pair{"deferred mask", &report->deferred_checks}}) {
    EXPECT_FALSE(checks->empty()) << form;
    for (const EngineFormCheck& c : *checks) {
      const std::string label =
          std::string(form) + ", " + std::string(to_string(c.target)) + " on " + c.backend;
      EXPECT_TRUE(c.pass) << label << ": " << c.error << " max error " << c.comparison.max_abs_error
                          << ", " << c.comparison.over_tolerance << " pixels over, "
                          << c.comparison.ambiguous << " ambiguous; camera agreement "
                          << c.camera_agreement;
      if (c.target != Target::hlsl_dx9) {
        EXPECT_EQ(c.map_format, param.format) << label;
        forms.insert(std::string(form) + " on " + c.backend);
      }
    }
  }
  EXPECT_EQ(forms, (std::set<std::string>{"function form on vulkan", "function form on gl",
                                          "deferred mask on vulkan", "deferred mask on gl"}));
}

INSTANTIATE_TEST_SUITE_P(Default, MapFormatConformance, ::testing::ValuesIn(kCases),
                         [](const auto& param_info) {
                           return test_name(param_info.param.variant) + "_" +
                                  std::string(to_string(param_info.param.format));
                         });

}  // namespace
}  // namespace penumbra::testing
