// Bad input to eval and verify (docs/robustness.md, "Bad input"): exit 2 and
// one message naming the argument or file, found before any device work.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "cli_harness.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

// verify writes OUT/verify.json, or --results: a file it cannot write is
// refused before the checks run (here before the device, which does not
// exist). A library that takes no files is verified: cli_read_only_test.
TEST(BadRuntimeInput, VerifyRefusesAResultsFileItCannotWrite) {
  ScratchDir dir("bad-verify");
  const auto manifest = dir.write(
      "m.json", R"({"schema": 1, "targets": ["spirv"], "sets": [{"technique": "hard"}]})");
  const auto lib = dir.path() / "lib";
  const CliRun built =
      run_penumbra("build -q --no-cache '" + manifest.string() + "' -o '" + lib.string() + "'");
  ASSERT_EQ(built.exit_code, 0) << built.err;
  const std::string verify = "verify '" + lib.string() + "' --device no-such-device-anywhere";

  std::filesystem::create_directory(lib / "verify.json");
  const CliRun blocked = run_penumbra(verify);
  EXPECT_EQ(blocked.exit_code, 2) << blocked.err;
  EXPECT_THAT(blocked.err, HasSubstr((lib / "verify.json").string()));
  EXPECT_THAT(blocked.err, HasSubstr("is a directory"));
  std::filesystem::remove(lib / "verify.json");

  for (const std::string& results :
       {(dir.path() / "missing" / "r.json").string(), dir.path().string()}) {
    const CliRun refused = run_penumbra(verify + " --results '" + results + "'");
    EXPECT_EQ(refused.exit_code, 2) << refused.err;
    EXPECT_THAT(refused.err, HasSubstr("--results " + results));
    EXPECT_THAT(refused.err, HasSubstr("allowed:"));
  }
}

// An unknown --map-format is refused with the allowed formats, before the
// library is read or verify.json touched.
TEST(BadRuntimeInput, VerifyRefusesAnUnknownMapFormat) {
  ScratchDir dir("bad-map-format");
  const CliRun run =
      run_penumbra("verify '" + (dir.path() / "missing").string() + "' --map-format d15_unorm");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_THAT(run.err, HasSubstr("--map-format d15_unorm"));
  EXPECT_THAT(run.err, HasSubstr("allowed: d32_float, d24_unorm, d16_unorm"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "missing"));
}

}  // namespace
}  // namespace penumbra::testing
