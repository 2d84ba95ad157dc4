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
// `variable` is given, the environment's `variable` set to `value` while
// verify looks for Wine and the host.
Result<TargetRun> d3d9_run(bool wine, const char* variable = nullptr, const char* value = nullptr) {
  auto compiler = recorded_hlsl_compiler();
  if (!compiler) return compiler.error();
  auto built = TemporaryLibrary::build({*find_default_variant("hard")}, {Target::hlsl_dx9},
                                       {.jobs = 1, .hlsl = {.compiler = *compiler}});
  if (!built) return built.error();
  auto engine = Engine::create({.device = "", .validation = false}, ignore_diagnostics());
  if (!engine) return engine.error();
  const char* before = variable ? std::getenv(variable) : nullptr;
  const std::string kept = before ? before : "";
  if (variable) ::setenv(variable, value, 1);
  auto report =
      verify_library((*built)->library(), **engine,
                     {.variants = {},
                      .targets = {},
                      .skipped = wine ? std::vector<std::string>{"gl"}
                                      : std::vector<std::string>{"gl", "d3d9", "d3d10", "d3d11"},
                      .paths = {"d3d9"}},
                     ignore_diagnostics());
  if (variable && before) ::setenv(variable, kept.c_str(), 1);
  if (variable && !before) ::unsetenv(variable);
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
  auto run = d3d9_run(true, "PATH", "/nonexistent");
  ASSERT_TRUE(run) << run.error().to_string();
  EXPECT_FALSE(run->executed);
  EXPECT_NE(run->not_executed.find("wine not found (Debian: apt-get install wine64 wine)"),
            std::string::npos)
      << run->not_executed;
}

// The note names the cause a user can act on, not a package to install.
TEST(RuntimesNotExecuted, WhenTheHostNamedDoesNotExist) {
  auto run = d3d9_run(true, "PENUMBRA_D3D_HOST", "/nonexistent/penumbra_d3d_host.exe");
  ASSERT_TRUE(run) << run.error().to_string();
  EXPECT_FALSE(run->executed);
  EXPECT_EQ(run->not_executed,
            "PENUMBRA_D3D_HOST names /nonexistent/penumbra_d3d_host.exe, which does not exist");
}

}  // namespace
}  // namespace penumbra::testing
