// verify's Direct3D runtime paths when they cannot or should not run: every
// run reported not executed, with the reason, and nothing started.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "default_library.hpp"
#include "hlsl_compiler.hpp"
#include "penumbra/verify/verify.hpp"

namespace penumbra::testing {
namespace {

// The d3d9 run of `hard`, verified with `wine` as given and, when
// `search_path` is given, that PATH while verify looks for Wine.
Result<TargetRun> d3d9_run(bool wine, const char* search_path = nullptr) {
  auto compiler = recorded_hlsl_compiler();
  if (!compiler) return compiler.error();
  auto built = TemporaryLibrary::build({*find_default_variant("hard")}, {Target::hlsl_dx9},
                                       {.jobs = 1, .hlsl = {.compiler = *compiler}});
  if (!built) return built.error();
  auto engine = Engine::create({.device = "", .validation = false}, ignore_diagnostics());
  if (!engine) return engine.error();
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  if (search_path) ::setenv("PATH", search_path, 1);
  auto report =
      verify_library((*built)->library(), **engine,
                     {.variants = {}, .targets = {}, .gl = false, .wine = wine, .paths = {"d3d9"}},
                     ignore_diagnostics());
  ::setenv("PATH", path.c_str(), 1);
  if (!report) return report.error();
  return report->variants.at(0).runs.at(0);
}

TEST(RuntimesNotExecuted, WhenSkipped) {
  auto run = d3d9_run(false);
  ASSERT_TRUE(run) << run.error().to_string();
  EXPECT_EQ(run->backend, "d3d9");
  EXPECT_FALSE(run->executed);
  EXPECT_EQ(run->not_executed, "not requested (--no-wine)");
}

TEST(RuntimesNotExecuted, WithoutWine) {
  auto run = d3d9_run(true, "/nonexistent");
  ASSERT_TRUE(run) << run.error().to_string();
  EXPECT_FALSE(run->executed);
  EXPECT_NE(run->not_executed.find("wine not found (Debian: apt-get install wine64 wine)"),
            std::string::npos)
      << run->not_executed;
}

}  // namespace
}  // namespace penumbra::testing
