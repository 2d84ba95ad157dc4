// Bad input gets exit code 2, a message naming what is wrong and where, and
// no output written (the exit codes of cli/exit_codes.hpp).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cli_harness.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

constexpr const char* kValidSet = R"({"technique": ["hard"]})";

std::string manifest_with_set(const std::string& set) {
  return R"({"schema": 1, "targets": ["spirv", "hlsl_dx9"], "sets": [)" + set + "]}";
}

class BuildErrors : public ::testing::Test {
 protected:
  ScratchDir dir{"build-errors"};

  // Runs `penumbra build` on `manifest_text`; asserts exit 2 and that OUT was
  // never created. Returns stderr.
  std::string build_fails(const std::string& manifest_text) {
    const auto manifest = dir.write("manifest.json", manifest_text);
    const auto out = dir.path() / "out";
    const CliRun run = run_penumbra("build '" + manifest.string() + "' -o '" + out.string() + "'");
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << "partial output left behind";
    EXPECT_EQ(dir.entry_count(), 1u) << "staging left behind";  // only manifest.json
    EXPECT_THAT(run.err, HasSubstr("manifest.json"));
    return run.err;
  }
};

TEST_F(BuildErrors, MalformedJson) {
  const std::string err = build_fails(R"({"schema": 1, "sets": [ )");
  EXPECT_THAT(err, HasSubstr("line"));
}

TEST_F(BuildErrors, UnknownTechnique) {
  const std::string err = build_fails(manifest_with_set(R"({"technique": ["vsm"]})"));
  EXPECT_THAT(err, HasSubstr("/sets/0/technique"));
  EXPECT_THAT(err, HasSubstr("vsm"));
  EXPECT_THAT(err, HasSubstr("pcss"));  // lists what is allowed
}

TEST_F(BuildErrors, UnknownTarget) {
  const std::string err =
      build_fails(R"({"schema": 1, "targets": ["metal"], "sets": [{"technique": ["hard"]}]})");
  EXPECT_THAT(err, HasSubstr("/targets/0"));
  EXPECT_THAT(err, HasSubstr("metal"));
  EXPECT_THAT(err, HasSubstr("hlsl_dx9"));
}

TEST_F(BuildErrors, SampleCountZero) {
  const std::string err = build_fails(manifest_with_set(
      R"({"technique": ["pcf_poisson"], "pcf_samples": [0], "disk": ["whitepaper16"]})"));
  EXPECT_THAT(err, HasSubstr("/sets/0/pcf_samples/0"));
  EXPECT_THAT(err, HasSubstr("1..128"));
}

TEST_F(BuildErrors, SampleCountOver128) {
  const std::string err = build_fails(
      R"({"schema": 1, "disks": {"poisson": {"method": "best_candidate", "seed": 1}},
          "sets": [{"technique": ["pcss"], "blocker_samples": [129], "pcf_samples": [16],
                    "disk": ["poisson"]}]})");
  EXPECT_THAT(err, HasSubstr("/sets/0/blocker_samples/0"));
  EXPECT_THAT(err, HasSubstr("129"));
  EXPECT_THAT(err, HasSubstr("1..128"));
}

// Manifest errors lead with FILE:LINE:COL of the offending value, as a
// compiler's do.
TEST_F(BuildErrors, ErrorsPointAtTheLineAndColumnOfTheValue) {
  const std::string err = build_fails(
      "{\"schema\": 1,\n"
      " \"targets\": [\"spirv\"],\n"
      " \"sets\": [{\"technique\": [\"hard\"]},\n"
      "          {\"technique\": \"minmax_pcf\", \"kernel\": 8, \"traversal\": \"foo\"}]}\n");
  EXPECT_THAT(err, HasSubstr("manifest.json:4:65: error: /sets/1/traversal: unknown traversal "
                             "'foo'"));
  EXPECT_THAT(err, ::testing::Not(HasSubstr("penumbra: error")));
}

TEST_F(BuildErrors, AValueInsideAListIsPointedAt) {
  const std::string err = build_fails(
      "{\"schema\": 1,\n \"targets\": [\"spirv\",\n   \"metal\"],\n"
      " \"sets\": [{\"technique\": [\"hard\"]}]}");
  EXPECT_THAT(err, HasSubstr("manifest.json:3:4: error: /targets/1: unknown target 'metal'"));
}

TEST_F(BuildErrors, MalformedJsonIsPointedAt) {
  const std::string err = build_fails("{\"schema\": 1,\n  \"sets\": [}");
  EXPECT_THAT(err, HasSubstr("manifest.json:2:12: error: malformed JSON"));
}

TEST_F(BuildErrors, MissingManifestFile) {
  const auto out = dir.path() / "out";
  const CliRun run = run_penumbra("build '" + (dir.path() / "absent.json").string() + "' -o '" +
                                  out.string() + "'");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("absent.json"));
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST_F(BuildErrors, FailedBuildKeepsThePreviousOutput) {
  const auto out = dir.path() / "out";
  std::filesystem::create_directories(out);
  dir.write("out/keep.txt", "previous build");
  const auto manifest = dir.write("manifest.json", manifest_with_set(R"({"technique": ["nope"]})"));
  const CliRun run = run_penumbra("build '" + manifest.string() + "' -o '" + out.string() + "'");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(std::filesystem::exists(out / "keep.txt"));
  EXPECT_EQ(dir.entry_count(), 3u);  // manifest.json, out/, out/keep.txt
}

TEST(CliUsage, UnknownSubcommandIsExit2) {
  const CliRun run = run_penumbra("frobnicate");
  EXPECT_EQ(run.exit_code, 2);
}

TEST(CliUsage, ListPrintsVariantsOfTheDefaultManifest) {
  const CliRun run =
      run_penumbra(std::string("list '") + PENUMBRA_SOURCE_DIR + "/permutations/default.json'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("pcss_b16_p16_whitepaper16\n"));
  EXPECT_THAT(run.out, HasSubstr("pcf_grid_k7\n"));
  EXPECT_THAT(run.out, HasSubstr("hard\n"));
}

TEST(CliUsage, DiskCountZeroIsRejected) {
  const CliRun run = run_penumbra("disk --count 0");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("1..128"));
  EXPECT_TRUE(run.out.empty());
}

TEST(CliUsage, DiskPrintsJson) {
  const CliRun run = run_penumbra("disk --count 7 --seed 3");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("\"points\""));
  EXPECT_THAT(run.out, HasSubstr("\"normalized_min_distance\""));
}

// `embed` takes a library, or --parts alone; each misuse names what it needs
// and writes nothing.
TEST(CliUsage, EmbedWithoutALibraryOrWithBothFormsIsExit2) {
  ScratchDir dir{"embed-usage"};
  const std::string out = " -o '" + (dir.path() / "out").string() + "'";
  const CliRun none = run_penumbra("embed --name shadows" + out);
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_THAT(none.err, HasSubstr("library"));
  EXPECT_THAT(none.err, HasSubstr("--parts"));
  const CliRun both = run_penumbra("embed some/library --parts 4 --name shadows" + out);
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_THAT(both.err, HasSubstr("--parts"));
  const CliRun range = run_penumbra("embed --parts 0 --name shadows" + out);
  EXPECT_EQ(range.exit_code, 2);
  EXPECT_THAT(range.err, HasSubstr("--parts"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out"));
}

}  // namespace
}  // namespace penumbra::testing
