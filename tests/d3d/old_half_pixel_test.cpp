// The D3D9 half pixel proved on a real Direct3D 9 runtime (Wine's d3d9):
// the library as built passes verify's d3d9 path, and the same library with
// the half pixel's old sign restored in its hlsl_dx9 vertex shaders (text,
// then bytecode by vkd3d-compiler) fails it, on the maps and the queries.
#include <gtest/gtest.h>

#include <chrono>

#include "default_library.hpp"
#include "hlsl_compiler.hpp"
#include "penumbra/support/atomic_file.hpp"
#include "penumbra/support/file.hpp"
#include "penumbra/support/process.hpp"
#include "penumbra/verify/verify.hpp"

namespace penumbra::testing {
namespace {

struct D3d9Results {
  std::size_t maps = 0;         // depth checks of d3d9's own maps
  std::size_t maps_failed = 0;  // of those, failed
  std::size_t runs = 0;         // d3d9 runs executed
  std::size_t runs_failed = 0;
};

Result<D3d9Results> verify_on_d3d9(const Library& library) {
  auto engine = Engine::create({.device = "", .validation = false}, ignore_diagnostics());
  if (!engine) return engine.error();
  auto report = verify_library(
      library, **engine,
      {.variants = {}, .targets = {Target::hlsl_dx9}, .skipped = paths_skipped_by("--no-gl")},
      ignore_diagnostics());
  if (!report) return report.error();
  D3d9Results results;
  for (const DepthCheck& depth : report->depth_checks) {
    if (depth.backend != "d3d9") continue;
    ++results.maps;
    results.maps_failed += depth.pass ? 0 : 1;
  }
  for (const VariantRun& variant : report->variants) {
    for (const TargetRun& run : variant.runs) {
      if (run.backend != "d3d9") continue;
      if (!run.executed) return make_error(Error::Kind::device, "d3d9", run.not_executed);
      ++results.runs;
      results.runs_failed += run.pass ? 0 : 1;
    }
  }
  return results;
}

// Turns `fixed` back into `old` in every hlsl_dx9 vertex shader of `library`
// and compiles each again with `compiler`; returns how many it changed.
Result<int> restore(const Library& library, const std::filesystem::path& compiler,
                    const std::string& fixed, const std::string& old) {
  int changed = 0;
  for (const LibraryVariant& entry : library.variants) {
    for (const auto& [pass, by_target] : entry.passes) {
      const auto files = by_target.find(Target::hlsl_dx9);
      if (files == by_target.end() || !files->second.vert_bytecode) continue;
      const auto text_path = library.root / files->second.vert;
      auto text = read_file(text_path);
      if (!text) return text.error();
      const std::size_t at = text->find(fixed);
      if (at == std::string::npos) continue;
      text->replace(at, fixed.size(), old);
      PENUMBRA_TRY(write_file_atomic(text_path, *text));
      const auto bytecode = library.root / files->second.vert_bytecode->path;
      auto run = run_process({compiler.string(), "-x", "hlsl", "-p", "vs_3_0", "-b", "d3dbc", "-e",
                              "main", "-o", bytecode.string(), text_path.string()},
                             std::chrono::seconds(60));
      if (!run) return run.error();
      if (run->exit_code != 0)
        return make_error(Error::Kind::compile, text_path.string(), run->output);
      ++changed;
    }
  }
  return changed;
}

TEST(OldHalfPixel, TheOldSignFailsOnDirect3D9AndTheFixedOnePasses) {
  auto compiler = recorded_hlsl_compiler();
  ASSERT_TRUE(compiler) << compiler.error().to_string();
  // A point-sampled query, and one whose min-max chain is drawn level by level.
  std::vector<Variant> variants;
  for (const char* name : {"hard", "minmax_pcf_k8"})
    variants.push_back(*find_default_variant(name));
  auto built = TemporaryLibrary::build(variants, {Target::hlsl_dx9},
                                       {.jobs = 2, .hlsl = {.compiler = *compiler}});
  ASSERT_TRUE(built) << built.error().to_string();
  const Library& library = (*built)->library();

  auto fixed = verify_on_d3d9(library);
  ASSERT_TRUE(fixed) << fixed.error().to_string();
  EXPECT_GT(fixed->maps, 0u);
  EXPECT_EQ(fixed->maps_failed, 0u);
  EXPECT_EQ(fixed->runs, 2u);
  EXPECT_EQ(fixed->runs_failed, 0u);

  auto changed =
      restore(library, *compiler, "gl_Position.y = gl_Position.y - gl_HalfPixel.y * gl_Position.w;",
              "gl_Position.y = gl_Position.y + gl_HalfPixel.y * gl_Position.w;");
  ASSERT_TRUE(changed) << changed.error().to_string();
  EXPECT_GT(*changed, 0) << "no hlsl_dx9 vertex shader has the half-pixel fixup";
  auto old = verify_on_d3d9(library);
  ASSERT_TRUE(old) << old.error().to_string();
  EXPECT_EQ(old->maps_failed, old->maps) << "every map one row off";
  EXPECT_EQ(old->runs_failed, old->runs) << "every query one row off";
}

}  // namespace
}  // namespace penumbra::testing
