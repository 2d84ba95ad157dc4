// Every variant of permutations/default.json, each target's own emitted
// shaders executed (SPIR-V as built, GLSL and HLSL text through glslang's
// front ends, GLSL also through the OpenGL driver when built with it) over
// the project's scenes and checked against the CPU reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "default_library.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/verify/verify.hpp"
#include "penumbra/vulkan/engine.hpp"
#include "validation_messages.hpp"

namespace penumbra::testing {
namespace {

class VariantConformance : public ::testing::TestWithParam<std::string> {};

TEST_P(VariantConformance, EveryTargetMatchesTheReferenceOnEveryScene) {
  auto built = build_default_variant(GetParam());
  ASSERT_TRUE(built) << built.error().to_string();
  auto engine = Engine::create({.device = "", .validation = true}, fail_on_validation_messages());
  ASSERT_TRUE(engine) << engine.error().to_string();
  auto report = verify_library((*built)->library(), **engine,
                               {.variants = {GetParam()}, .targets = {}, .skipped = {}},
                               ignore_diagnostics());
  ASSERT_TRUE(report.ok()) << report.error().to_string();
  for (const DepthCheck& depth : report->depth_checks) {
    EXPECT_TRUE(depth.pass) << "depth pass of " << to_string(depth.target) << " on " << depth.scene
                            << ": " << depth.mismatched << " of " << depth.texels << " texels off";
  }
  ASSERT_EQ(report->variants.size(), 1u);
  const Technique technique = report->variants[0].technique;
  // Every target's own minmax passes build a mip equal to the CPU mip on every scene.
  const Variant& variant = (*built)->library().variants.at(0).variant;
  const auto emitted = static_cast<std::size_t>(
      std::ranges::count_if(kAllTargets, [&](Target target) { return can_emit(variant, target); }));
  if (uses_minmax_mip(technique)) {
    EXPECT_EQ(report->minmax_checks.size(), emitted * reference::builtin_scenes().size());
  } else {
    EXPECT_TRUE(report->minmax_checks.empty());
  }
  for (const MinmaxCheck& mip : report->minmax_checks) {
    EXPECT_TRUE(mip.pass) << "min-max mip of " << to_string(mip.target) << " on " << mip.scene
                          << ": " << mip.mismatched << " of " << mip.texels << " nodes off, "
                          << mip.levels << " of " << mip.expected_levels << " levels " << mip.error;
  }
  std::set<Target> on_vulkan;
  for (const TargetRun& run : report->variants[0].runs) {
    const std::string label = std::string(to_string(run.target)) + " on " + run.backend;
    if (!run.executed) {
      // The bytecode path and the Direct3D runtimes need a library built
      // with an HLSL compiler: tests/bytecode and tests/d3d run them.
      EXPECT_TRUE(run.backend == "gl" || run.backend == "bytecode" ||
                  run.backend.starts_with("d3d"))
          << label << " must run: " << run.not_executed;
      continue;
    }
    ASSERT_TRUE(run.error.empty()) << label << ": " << run.error;
    if (run.backend == "vulkan") on_vulkan.insert(run.target);
    ASSERT_EQ(run.scenes.size(), reference::builtin_scenes().size()) << label;
    for (const SceneRun& scene : run.scenes) {
      const auto& c = scene.comparison;
      EXPECT_TRUE(c.pass) << label << " (" << run.execution.front_end << ") on " << scene.scene
                          << ": max error " << c.max_abs_error << " (tolerance " << c.tolerance
                          << "), " << c.over_tolerance << " pixels over, " << c.ambiguous
                          << " ambiguous of " << c.pixels;
      // A scene that leaves almost everything ambiguous would check nothing.
      EXPECT_GT(c.compared, c.pixels * 9 / 10) << label << " " << scene.scene;
      // The tolerance is the Vulkan bound for any conforming device; on
      // llvmpipe (lavapipe and Mesa GL) filtering is exact to float rounding,
      // so anything larger there is a real error (a 1% radius error is ~8e-3).
      if (run.device.find("llvmpipe") != std::string::npos) {
        EXPECT_LT(c.max_abs_error, 1e-4) << label << " on " << scene.scene;
      }
      // screen_blur's chain, checked step by step on the GPU's own images:
      // the blur of its factor and the composite of its blurred factor.
      if (technique == Technique::screen_blur) {
        ASSERT_TRUE(scene.blur && scene.composite) << label << " on " << scene.scene;
        EXPECT_TRUE(scene.blur->pass)
            << label << " on " << scene.scene << ": blur max error " << scene.blur->max_abs_error
            << ", " << scene.blur->over_tolerance << " values over";
        EXPECT_TRUE(scene.composite->pass)
            << label << " on " << scene.scene << ": composite max error "
            << scene.composite->max_abs_error << ", " << scene.composite->over_tolerance
            << " values over";
        EXPECT_EQ(scene.blur->values, static_cast<std::size_t>(c.pixels)) << label;
        EXPECT_EQ(scene.composite->values, 4 * static_cast<std::size_t>(c.pixels)) << label;
      } else {
        EXPECT_FALSE(scene.blur || scene.composite) << label;
      }
      // A count of point compares, 1 - C / K^2 in float: bit-exact everywhere.
      if (technique == Technique::minmax_pcf) {
        EXPECT_EQ(c.tolerance, 0.0) << label;
        EXPECT_EQ(c.max_abs_error, 0.0) << label << " on " << scene.scene;
      }
    }
  }
  EXPECT_EQ(on_vulkan.size(), emitted) << "every target's own shaders must execute";
  // The function form, where the variant has one, as an engine's own
  // shaders call it: every text target on Vulkan, and GLSL on the driver.
  std::set<std::pair<Target, std::string>> drawn;
  for (const EngineFormCheck& c : report->function_checks) {
    const std::string label = std::string(to_string(c.target)) + " on " + c.backend;
    EXPECT_TRUE(c.pass) << "function form, " << label << ": " << c.error << " max error "
                        << c.comparison.max_abs_error << ", " << c.comparison.over_tolerance
                        << " pixels over; camera agreement " << c.camera_agreement;
    drawn.emplace(c.target, c.backend);
  }
  const auto& function = (*built)->library().variants.at(0).function;
  for (const auto& [target, form] : function) {
    EXPECT_TRUE(drawn.contains({target, "vulkan"})) << to_string(target);
    if (target == Target::glsl330 || target == Target::glsl450) {
      EXPECT_TRUE(drawn.contains({target, "gl"})) << to_string(target);
    }
  }
  EXPECT_EQ(drawn.size(), function.size() + (function.empty() ? 0 : 2));
  // The deferred pass, where the variant has one, over the camera's depth:
  // every target on Vulkan, and GLSL on the driver.
  std::set<std::pair<Target, std::string>> masked;
  for (const EngineFormCheck& c : report->deferred_checks) {
    const std::string label = std::string(to_string(c.target)) + " on " + c.backend;
    EXPECT_TRUE(c.pass) << "deferred pass, " << label << ": " << c.error << " max error "
                        << c.comparison.max_abs_error << ", " << c.comparison.over_tolerance
                        << " pixels over, " << c.comparison.ambiguous
                        << " ambiguous; camera agreement " << c.camera_agreement;
    masked.emplace(c.target, c.backend);
  }
  const LibraryVariant& entry = (*built)->library().variants.at(0);
  const bool deferred = entry.reflection.contains(PassKind::deferred);
  EXPECT_EQ(deferred, !function.empty()) << "the deferred pass goes with the function form";
  if (deferred) {
    for (Target target : entry.variant.targets) {
      EXPECT_TRUE(masked.contains({target, "vulkan"})) << to_string(target);
    }
  }
  EXPECT_EQ(masked.size(), deferred ? entry.variant.targets.size() + 2 : 0);
}

INSTANTIATE_TEST_SUITE_P(Default, VariantConformance, ::testing::ValuesIn(default_variant_names()),
                         [](const auto& param_info) { return test_name(param_info.param); });

}  // namespace
}  // namespace penumbra::testing
