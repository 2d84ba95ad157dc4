// The Direct3D bytecode executed as Proton executes it: every default
// variant's .d3dbc/.dxbc files translated to SPIR-V by vkd3d-compiler, run on
// the Vulkan engine bound by the reflection's registers, and checked against
// the CPU reference on every scene (verify's "bytecode" path); and the check
// failing on bytecode or reflection that is not the variant's; and each
// function form inside an engine's own HLSL compiled to that bytecode.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "default_library.hpp"
#include "hlsl_compiler.hpp"
#include "penumbra/compiler/targets.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/support/atomic_file.hpp"
#include "penumbra/verify/verify.hpp"
#include "validation_messages.hpp"

namespace penumbra::testing {
namespace {

// Every target a Direct3D engine loads as bytecode.
std::vector<Target> bytecode_targets() {
  std::vector<Target> out;
  for (Target target : kAllTargets) {
    if (bytecode_format(target, ShaderStage::fragment)) out.push_back(target);
  }
  return out;
}

Result<std::unique_ptr<TemporaryLibrary>> build_with_bytecode(const std::string& name) {
  auto compiler = recorded_hlsl_compiler();
  if (!compiler) return compiler.error();
  const Variant* variant = find_default_variant(name);
  if (variant == nullptr) return make_error(Error::Kind::bad_input, name, "no such variant");
  return TemporaryLibrary::build({*variant}, bytecode_targets(),
                                 {.jobs = 2, .hlsl = {.compiler = *compiler}});
}

// verify's report on `name` in `library`, on the bytecode path alone (the
// Vulkan path's runs of the same targets are tests/conformance's).
Result<VerifyReport> bytecode_report(const Library& library, const std::string& name) {
  auto compiler = recorded_hlsl_compiler();
  if (!compiler) return compiler.error();
  auto engine = Engine::create({.device = "", .validation = true}, fail_on_validation_messages());
  if (!engine) return engine.error();
  return verify_library(
      library, **engine,
      {.variants = {name},
       .targets = bytecode_targets(),
       .skipped = {"gl", "d3d9", "d3d10", "d3d11"},  // tests/d3d runs the runtimes
       .paths = {"bytecode"},
       .bytecode = {.compiler = *compiler}},
      ignore_diagnostics());
}

// The bytecode path's runs of `name` in `library`.
Result<std::vector<TargetRun>> bytecode_runs(const Library& library, const std::string& name) {
  PENUMBRA_TRY_ASSIGN(const VerifyReport report, bytecode_report(library, name));
  std::vector<TargetRun> out;
  for (const TargetRun& run : report.variants.at(0).runs) {
    if (run.backend == "bytecode") out.push_back(run);
  }
  return out;
}

class BytecodeExecution : public ::testing::TestWithParam<std::string> {};

TEST_P(BytecodeExecution, EveryDirect3DTargetsBytecodeMatchesTheReference) {
  auto built = build_with_bytecode(GetParam());
  ASSERT_TRUE(built) << built.error().to_string();
  auto report = bytecode_report((*built)->library(), GetParam());
  ASSERT_TRUE(report) << report.error().to_string();
  std::vector<TargetRun> runs_on_bytecode;
  for (const TargetRun& run : report->variants.at(0).runs) {
    if (run.backend == "bytecode") runs_on_bytecode.push_back(run);
  }
  const std::vector<TargetRun>* runs = &runs_on_bytecode;
  const Variant& variant = *find_default_variant(GetParam());
  ASSERT_EQ(runs->size(), std::ranges::count_if(bytecode_targets(), [&](Target target) {
              return can_emit(variant, target);
            }));
  for (const TargetRun& run : *runs) {
    const std::string label(to_string(run.target));
    ASSERT_TRUE(run.executed) << label << ": " << run.not_executed;
    ASSERT_TRUE(run.error.empty()) << label << ": " << run.error;
    EXPECT_NE(run.execution.front_end.find("vkd3d-compiler"), std::string::npos) << label;
    ASSERT_EQ(run.scenes.size(), reference::builtin_scenes().size()) << label;
    for (const SceneRun& scene : run.scenes) {
      const auto& c = scene.comparison;
      EXPECT_TRUE(scene.pass()) << label << " on " << scene.scene << ": max error "
                                << c.max_abs_error << " (tolerance " << c.tolerance << "), "
                                << c.over_tolerance << " pixels over";
    }
  }
  // The function form inside an engine's own HLSL, compiled to each
  // target's bytecode by vkd3d-compiler and translated, as a Direct3D
  // engine's shaders run under Proton.
  std::set<Target> drawn;
  for (const EngineFormCheck& c : report->function_checks) {
    if (c.backend != "bytecode") continue;
    const std::string label = "function form, " + std::string(to_string(c.target));
    EXPECT_TRUE(c.pass) << label << ": " << c.error << " max error " << c.comparison.max_abs_error
                        << ", " << c.comparison.over_tolerance << " pixels over; camera agreement "
                        << c.camera_agreement;
    EXPECT_NE(c.execution.front_end.find("vkd3d-compiler hlsl to"), std::string::npos) << label;
    drawn.insert(c.target);
  }
  EXPECT_EQ(drawn.size(), has_function_form(variant.technique) ? runs->size() : 0u);
  // The deferred pass's bytecode over the camera's depth, translated.
  std::set<Target> masked;
  for (const EngineFormCheck& c : report->deferred_checks) {
    if (c.backend != "bytecode") continue;
    const std::string label = "deferred pass, " + std::string(to_string(c.target));
    EXPECT_TRUE(c.pass) << label << ": " << c.error << " max error " << c.comparison.max_abs_error
                        << ", " << c.comparison.over_tolerance << " pixels over; camera agreement "
                        << c.camera_agreement;
    masked.insert(c.target);
  }
  EXPECT_EQ(masked.size(), runs_pass(PassKind::deferred, variant) ? runs->size() : 0u);
}

INSTANTIATE_TEST_SUITE_P(Default, BytecodeExecution, ::testing::ValuesIn(default_variant_names()),
                         [](const auto& param_info) { return test_name(param_info.param); });

// The pcf_grid_k3 library with its hlsl_dx9 query bytecode replaced by
// pcf_grid_k7's: same registers, another kernel.
TEST(BytecodeExecutionCheck, AnotherVariantsBytecodeFails) {
  auto k3 = build_with_bytecode("pcf_grid_k3");
  ASSERT_TRUE(k3) << k3.error().to_string();
  auto k7 = build_with_bytecode("pcf_grid_k7");
  ASSERT_TRUE(k7) << k7.error().to_string();
  const auto query = [](const Library& library) {
    return *library.variants.at(0).passes.at(PassKind::query).at(Target::hlsl_dx9).frag_bytecode;
  };
  std::filesystem::copy_file((*k7)->library().root / query((*k7)->library()).path,
                             (*k3)->library().root / query((*k3)->library()).path,
                             std::filesystem::copy_options::overwrite_existing);
  auto runs = bytecode_runs((*k3)->library(), "pcf_grid_k3");
  ASSERT_TRUE(runs) << runs.error().to_string();
  for (const TargetRun& run : *runs) {
    ASSERT_TRUE(run.executed && run.error.empty()) << to_string(run.target) << ": " << run.error;
    EXPECT_EQ(run.pass, run.target != Target::hlsl_dx9) << to_string(run.target);
  }
}

// A reflection naming the wrong t# register for hlsl_dx10's map, and
// bytecode that is not bytecode: failed runs, with the reason.
TEST(BytecodeExecutionCheck, WrongRegisterOrCorruptBytecodeFails) {
  auto built = build_with_bytecode("hard");
  ASSERT_TRUE(built) << built.error().to_string();
  Library library = (*built)->library();
  LibraryVariant& hard = library.variants.at(0);
  for (TextureBinding& texture :
       hard.reflection.at(PassKind::query).at(Target::hlsl_dx10).frag.textures) {
    texture.reg = "t9";
  }
  const BytecodeFile dx9 = *hard.passes.at(PassKind::query).at(Target::hlsl_dx9).frag_bytecode;
  ASSERT_TRUE(write_file_atomic(library.root / dx9.path, "not Direct3D bytecode"));
  auto runs = bytecode_runs(library, "hard");
  ASSERT_TRUE(runs) << runs.error().to_string();
  ASSERT_EQ(runs->size(), bytecode_targets().size());
  for (const TargetRun& run : *runs) {
    if (run.target != Target::hlsl_dx9 && run.target != Target::hlsl_dx10) continue;
    EXPECT_TRUE(run.executed) << to_string(run.target);
    EXPECT_FALSE(run.pass) << to_string(run.target);
    const std::string expected = run.target == Target::hlsl_dx10 ? "register t9" : "vkd3d-compiler";
    EXPECT_NE(run.error.find(expected), std::string::npos) << run.error;
  }
}

// Without a translator, or without bytecode in the library, the path's runs
// are reported not executed, with the reason.
TEST(BytecodeExecutionCheck, NotExecutedWithoutTranslatorOrBytecode) {
  auto built = build_default_variant("hard", bytecode_targets());
  ASSERT_TRUE(built) << built.error().to_string();
  auto runs = bytecode_runs((*built)->library(), "hard");
  ASSERT_TRUE(runs) << runs.error().to_string();
  ASSERT_EQ(runs->size(), bytecode_targets().size());
  for (const TargetRun& run : *runs) {
    EXPECT_FALSE(run.executed) << to_string(run.target);
    EXPECT_NE(run.not_executed.find("--hlsl-compiler"), std::string::npos) << run.not_executed;
  }
  auto engine = Engine::create({.device = "", .validation = true}, fail_on_validation_messages());
  ASSERT_TRUE(engine) << engine.error().to_string();
  auto report = verify_library((*built)->library(), **engine,
                               {.variants = {"hard"},
                                .targets = bytecode_targets(),
                                .skipped = {"gl", "d3d9", "d3d10", "d3d11"}},
                               ignore_diagnostics());
  ASSERT_TRUE(report) << report.error().to_string();
  for (const TargetRun& run : report->variants.at(0).runs) {
    if (run.backend != "bytecode") continue;
    EXPECT_FALSE(run.executed);
    EXPECT_NE(run.not_executed.find("no HLSL compiler"), std::string::npos) << run.not_executed;
  }
}

}  // namespace
}  // namespace penumbra::testing
