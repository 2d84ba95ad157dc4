// `penumbra build` finds vkd3d-compiler (--hlsl-compiler, then
// PENUMBRA_HLSL_COMPILER, then sid-tools.sh's cache) and, without one, writes
// the text alone and says so in one line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cli_harness.hpp"
#include "hlsl_compiler.hpp"
#include "penumbra/library/library.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr const char* kManifest =
    R"({"schema": 1, "targets": ["hlsl_dx9", "hlsl_dx10", "hlsl_dx11"],)"
    R"( "sets": [{"technique": ["hard"]}]})";
constexpr const char* kNoBytecode = "no Direct3D bytecode made";

class CliBytecode : public ::testing::Test {
 protected:
  ScratchDir dir{"cli-bytecode"};

  // `penumbra build` of kManifest into out/ with `flags`, with a home and
  // cache that hold no compiler and `env` before them.
  CliRun build(const std::string& flags, const std::string& env) {
    const auto manifest = dir.write("manifest.json", kManifest);
    const std::string home = (dir.path() / "home").string();
    return run_penumbra("build '" + manifest.string() + "' -o '" + out().string() + "' " + flags,
                        "HOME='" + home + "' XDG_CACHE_HOME='" + home + "/cache' " + env);
  }
  std::filesystem::path out() const { return dir.path() / "out"; }

  // The bytecode files index.json lists.
  std::size_t listed_bytecode() const {
    auto library = load_library(out());
    if (!library.ok()) {
      ADD_FAILURE() << library.error().to_string();
      return 0;
    }
    std::size_t count = 0;
    for (const LibraryVariant& variant : library->variants) {
      for (const auto& [pass, by_target] : variant.passes) {
        for (const auto& [target, files] : by_target) {
          count += files.vert_bytecode.has_value() + files.frag_bytecode.has_value();
        }
      }
    }
    return count;
  }
};

TEST_F(CliBytecode, WithoutACompilerTheTextIsWrittenAndOneLineSaysSo) {
  const CliRun run = build("", "PENUMBRA_HLSL_COMPILER=");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto at = run.err.find(kNoBytecode);
  ASSERT_NE(at, std::string::npos) << run.err;
  EXPECT_EQ(run.err.find(kNoBytecode, at + 1), std::string::npos) << "said more than once";
  EXPECT_THAT(run.err, HasSubstr("--hlsl-compiler"));
  EXPECT_THAT(run.err, HasSubstr("scripts/lib/sid-tools.sh vkd3d"));
  EXPECT_TRUE(std::filesystem::exists(out() / "hlsl_dx9/hard/query.frag.hlsl"));
  EXPECT_FALSE(std::filesystem::exists(out() / "hlsl_dx9/hard/query.frag.d3dbc"));
  EXPECT_EQ(listed_bytecode(), 0u);
}

TEST_F(CliBytecode, TheFlagNamesTheCompiler) {
  auto compiler = recorded_hlsl_compiler();
  ASSERT_TRUE(compiler.ok()) << compiler.error().to_string();
  const CliRun run =
      build("--hlsl-compiler '" + compiler->string() + "'", "PENUMBRA_HLSL_COMPILER=");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.err, Not(HasSubstr(kNoBytecode)));
  // Per target: depth.vert, depth.frag, fullscreen.vert, query.frag,
  // deferred.vert and deferred.frag.
  EXPECT_THAT(run.out, HasSubstr("18 bytecode files"));
  EXPECT_EQ(listed_bytecode(), 18u);
  EXPECT_TRUE(std::filesystem::exists(out() / "hlsl_dx9/hard/query.frag.d3dbc"));
  EXPECT_TRUE(std::filesystem::exists(out() / "hlsl_dx9/hard/deferred.frag.d3dbc"));
  EXPECT_TRUE(std::filesystem::exists(out() / "hlsl_dx10/hard/query.frag.dxbc"));
  EXPECT_TRUE(std::filesystem::exists(out() / "hlsl_dx11/hard/query.frag.dxbc"));
}

TEST_F(CliBytecode, TheEnvironmentVariableNamesTheCompiler) {
  auto compiler = recorded_hlsl_compiler();
  ASSERT_TRUE(compiler.ok()) << compiler.error().to_string();
  const CliRun run = build("", "PENUMBRA_HLSL_COMPILER='" + compiler->string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.err, Not(HasSubstr(kNoBytecode)));
  EXPECT_EQ(listed_bytecode(), 18u);
}

TEST_F(CliBytecode, AMissingNamedCompilerIsAnError) {
  const CliRun run = build("--hlsl-compiler '" + (dir.path() / "absent").string() + "'", "");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_THAT(run.err, HasSubstr("--hlsl-compiler"));
  EXPECT_THAT(run.err, HasSubstr("absent"));
  EXPECT_FALSE(std::filesystem::exists(out()));
}

}  // namespace
}  // namespace penumbra::testing
