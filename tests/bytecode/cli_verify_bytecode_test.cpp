// `penumbra verify` finds vkd3d-compiler as `penumbra build` does
// (--hlsl-compiler, then PENUMBRA_HLSL_COMPILER, then sid-tools.sh's cache),
// runs the bytecode path with it, and refuses a compiler that is not there.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

#include "cli_harness.hpp"
#include "hlsl_compiler.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

constexpr const char* kManifest =
    R"({"schema": 1, "targets": ["hlsl_dx9", "hlsl_dx10"], "sets": [{"technique": ["hard"]}]})";

class CliVerifyBytecode : public ::testing::Test {
 protected:
  ScratchDir dir{"cli-verify-bytecode"};

  // `penumbra verify` of a library of kManifest built with the recorded
  // compiler, with `flags` and `env`, a home and cache that hold no compiler.
  CliRun verify(const std::string& flags, const std::string& env) {
    auto compiler = recorded_hlsl_compiler();
    EXPECT_TRUE(compiler.ok()) << compiler.error().to_string();
    const auto manifest = dir.write("manifest.json", kManifest);
    const std::string home = "HOME='" + (dir.path() / "home").string() + "' XDG_CACHE_HOME='" +
                             (dir.path() / "home/cache").string() + "' ";
    const CliRun built = run_penumbra("build '" + manifest.string() + "' -o '" + lib().string() +
                                      "' --hlsl-compiler '" + compiler->string() + "'");
    EXPECT_EQ(built.exit_code, 0) << built.err;
    return run_penumbra("verify '" + lib().string() + "' --no-gl " + flags, home + env);
  }
  std::filesystem::path lib() const { return dir.path() / "lib"; }
};

TEST_F(CliVerifyBytecode, TheFlagRunsTheBytecodePath) {
  auto compiler = recorded_hlsl_compiler();
  ASSERT_TRUE(compiler.ok()) << compiler.error().to_string();
  const CliRun run = verify("--hlsl-compiler '" + compiler->string() + "'", "");
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_THAT(run.out, HasSubstr("PASS hard [hlsl_dx9 on bytecode]"));
  EXPECT_THAT(run.out, HasSubstr("PASS hard [hlsl_dx10 on bytecode]"));
  // The same files on Wine's Direct3D 9 and 10, each drawing its own maps.
  EXPECT_THAT(run.out, HasSubstr("PASS hard [hlsl_dx9 on d3d9]"));
  EXPECT_THAT(run.out, HasSubstr("PASS hard [hlsl_dx10 on d3d10]"));
  EXPECT_THAT(run.out, HasSubstr("PASS depth pass [hlsl_dx9 on d3d9] on steps"));
  const auto report = read_file(lib() / "verify.json");
  ASSERT_TRUE(report.ok()) << report.error().to_string();
  EXPECT_THAT(*report, HasSubstr("vkd3d-compiler dxbc-tpf to SPIR-V (vs_4_0, ps_4_0)"));
  EXPECT_THAT(*report, HasSubstr("vkd3d-compiler d3dbc to SPIR-V (vs_3_0, ps_3_0)"));
}

TEST_F(CliVerifyBytecode, WithoutACompilerItsRunsAreNotExecuted) {
  const CliRun run = verify("--no-wine", "PENUMBRA_HLSL_COMPILER=");
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_THAT(run.out, HasSubstr("note: 2 bytecode runs not executed: no HLSL compiler"));
}

TEST_F(CliVerifyBytecode, AMissingNamedCompilerIsAnError) {
  for (const auto& [flags, env, named] :
       {std::tuple{"--hlsl-compiler '" + (dir.path() / "absent").string() + "'", std::string(),
                   "--hlsl-compiler"},
        std::tuple{std::string(),
                   "PENUMBRA_HLSL_COMPILER='" + (dir.path() / "absent").string() + "'",
                   "PENUMBRA_HLSL_COMPILER"}}) {
    const CliRun run = verify(flags, env);
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_THAT(run.err, HasSubstr(std::string(named) + ": "));
    EXPECT_THAT(run.err, HasSubstr("absent is not an executable file"));
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
  }
}

}  // namespace
}  // namespace penumbra::testing
