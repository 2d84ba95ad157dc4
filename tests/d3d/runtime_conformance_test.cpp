// Every default variant's Direct3D bytecode on its own runtime under Wine:
// hlsl_dx9 on d3d9, hlsl_dx10 on d3d10, hlsl_dx11 on d3d11 (verify's paths
// of those names), each drawing the scenes' maps itself, checked against
// the ray cast, and every query against the CPU reference. One verify run
// over the whole library, so that each runtime's host starts once and each
// scene's map is drawn once per runtime.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "default_library.hpp"
#include "hlsl_compiler.hpp"
#include "penumbra/compiler/targets.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/map_layout.hpp"
#include "penumbra/reference/cascades.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/verify/verify.hpp"

namespace penumbra::testing {
namespace {

const std::map<Target, std::string> kRuntimes = {
    {Target::hlsl_dx9, "d3d9"}, {Target::hlsl_dx10, "d3d10"}, {Target::hlsl_dx11, "d3d11"}};

TEST(Direct3DRuntimes, EveryDefaultVariantMatchesTheReferenceOnItsRuntime) {
  auto compiler = recorded_hlsl_compiler();
  ASSERT_TRUE(compiler) << compiler.error().to_string();
  auto built = TemporaryLibrary::build(default_variants(), hlsl_targets(),
                                       {.jobs = 2, .hlsl = {.compiler = *compiler}});
  ASSERT_TRUE(built) << built.error().to_string();
  auto engine = Engine::create({.device = "", .validation = false}, ignore_diagnostics());
  ASSERT_TRUE(engine) << engine.error().to_string();
  auto report = verify_library((*built)->library(), **engine,
                               {.variants = {},
                                .targets = hlsl_targets(),
                                .skipped = {"gl"},
                                .paths = {"d3d9", "d3d10", "d3d11"},
                                // compiles the engine's own HLSL around each function form
                                .bytecode = {.compiler = *compiler}},
                               ignore_diagnostics());
  ASSERT_TRUE(report) << report.error().to_string();

  std::size_t expected_runs = 0;
  for (const VariantRun& variant : report->variants) {
    for (Target target : find_default_variant(variant.name)->targets) {
      if (kRuntimes.contains(target)) ++expected_runs;
    }
    for (const TargetRun& run : variant.runs) {
      const std::string label =
          variant.name + " [" + std::string(to_string(run.target)) + " on " + run.backend + "]";
      EXPECT_EQ(run.backend, kRuntimes.at(run.target)) << label;
      ASSERT_TRUE(run.executed) << label << ": " << run.not_executed;
      ASSERT_TRUE(run.error.empty()) << label << ": " << run.error;
      EXPECT_NE(run.device.find("Wine's Direct3D"), std::string::npos) << label << run.device;
      ASSERT_EQ(run.scenes.size(), reference::builtin_scenes().size()) << label;
      for (const SceneRun& scene : run.scenes) {
        const auto& c = scene.comparison;
        EXPECT_TRUE(scene.pass()) << label << " on " << scene.scene << ": max error "
                                  << c.max_abs_error << " (tolerance " << c.tolerance << "), "
                                  << c.over_tolerance << " pixels over";
      }
    }
  }
  std::size_t runs = 0;
  for (const VariantRun& variant : report->variants) runs += variant.runs.size();
  EXPECT_EQ(runs, expected_runs);
  EXPECT_EQ(report->variants.size(), default_variants().size());
  // Each runtime's own maps, drawn by its own rasterizer, match the ray cast;
  // the Vulkan ones verify prepares the scenes with too.
  std::map<std::string, std::size_t> maps;
  for (const DepthCheck& depth : report->depth_checks) {
    EXPECT_TRUE(depth.pass) << "depth pass of " << to_string(depth.target) << " on "
                            << depth.backend << ", " << depth.scene << ": " << depth.mismatched
                            << " of " << depth.texels << " texels off";
    ++maps[depth.backend];
  }
  // One map per scene and map encoding the library's variants read.
  std::set<MapEncoding> encodings;
  for (const Variant& variant : default_variants()) encodings.insert(map_encoding(variant.keys));
  for (const auto& [target, runtime] : kRuntimes) {
    EXPECT_EQ(maps[runtime], reference::builtin_scenes().size() * encodings.size()) << runtime;
  }
  // Every function form inside an engine's own HLSL, compiled to bytecode,
  // loaded by its target's runtime and drawn over the report's stage, and
  // a directional light's in an atlas or array over each cascade of the
  // cascaded stage too.
  std::size_t function_forms = 0, deferred_passes = 0;
  for (const LibraryVariant& entry : (*built)->library().variants) {
    const Variant& variant = entry.variant;
    const std::size_t stages = map_encoding(variant.keys) == MapEncoding::orthographic &&
                                       map_layout(variant.keys) != MapLayout::single
                                   ? 1 + reference::cascaded_stage().cascades.size()
                                   : 1;
    function_forms += stages * entry.function.size();
    if (const auto deferred = entry.reflection.find(PassKind::deferred);
        deferred != entry.reflection.end()) {
      deferred_passes +=
          stages * std::ranges::count_if(deferred->second, [](const auto& by_target) {
            return kRuntimes.contains(by_target.first);
          });
    }
  }
  EXPECT_EQ(report->function_checks.size(), function_forms);
  for (const EngineFormCheck& c : report->function_checks) {
    EXPECT_EQ(c.backend, kRuntimes.at(c.target));
    EXPECT_TRUE(c.pass) << "function form of " << c.variant << " [" << to_string(c.target) << " on "
                        << c.backend << "]: " << c.error << " max error "
                        << c.comparison.max_abs_error << ", " << c.comparison.over_tolerance
                        << " pixels over; camera agreement " << c.camera_agreement;
  }
  // Every deferred pass's bytecode on its target's runtime, over the
  // camera's depth of the report's stage.
  EXPECT_EQ(report->deferred_checks.size(), deferred_passes);
  for (const EngineFormCheck& c : report->deferred_checks) {
    EXPECT_EQ(c.backend, kRuntimes.at(c.target));
    EXPECT_TRUE(c.pass) << "deferred pass of " << c.variant << " [" << to_string(c.target) << " on "
                        << c.backend << "]: " << c.error << " max error "
                        << c.comparison.max_abs_error << ", " << c.comparison.over_tolerance
                        << " pixels over; camera agreement " << c.camera_agreement;
  }
}

}  // namespace
}  // namespace penumbra::testing
