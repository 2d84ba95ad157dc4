// `penumbra verify` and `penumbra report` with --jobs: the same results for
// every N (verify.json byte for byte, the report's files less their timings),
// progress on stderr as each unit finishes, and none with -q; and verify's
// results the same for any number of device threads, and whether Mesa's
// shader JIT optimizes or not.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "cli_harness.hpp"
#include "penumbra/report/report.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// A map-only technique, a mip one, screen_blur's chain, PCSS; a text target
// with the GL path and a Direct3D one with its bytecode and runtime paths
// (which draw their own maps: their references are their own).
constexpr const char* kManifest = R"({
  "schema": 1,
  "targets": ["spirv", "glsl330", "hlsl_dx9"],
  "sets": [
    {"technique": ["hard"]},
    {"technique": ["pcss"], "blocker_samples": [16], "pcf_samples": [16], "disk": ["whitepaper16"]},
    {"technique": ["backprojection"]},
    {"technique": ["screen_blur"], "blur_radius": [2]}
  ]})";
constexpr std::size_t kPairs = 4 * 3;        // (variant, target) pairs verify checks
constexpr std::size_t kPictureRuns = 4 * 6;  // paths: spirv 1, glsl330 2, hlsl_dx9 3

// The progress lines "[done/total] seconds s unit" of `err`, as "done/total".
std::vector<std::string> progress(const std::string& err) {
  std::vector<std::string> lines;
  const std::regex line(R"(^\[(\d+/\d+)\] \d+\.\d s \S.*$)");
  std::istringstream in(err);
  for (std::string text; std::getline(in, text);) {
    std::smatch m;
    if (std::regex_match(text, m, line)) lines.push_back(m[1]);
  }
  return lines;
}

std::vector<std::string> counted(std::size_t total) {
  std::vector<std::string> lines;
  for (std::size_t i = 1; i <= total; ++i) {
    lines.push_back(std::to_string(i) + "/" + std::to_string(total));
  }
  return lines;
}

class Jobs : public EvalFixture {
 protected:
  static void SetUpTestSuite() { set_up_eval("jobs", kManifest); }
  static void TearDownTestSuite() { tear_down_eval(); }

  static std::string verify_json() {
    auto text = read_file(lib() / "verify.json");
    EXPECT_TRUE(text.ok());
    return text ? *text : "";
  }
};

TEST_F(Jobs, VerifyGivesTheSameResultsForAnyNumberOfJobs) {
  const CliRun one = run_penumbra("verify '" + lib().string() + "' --jobs 1");
  ASSERT_EQ(one.exit_code, 0) << one.out << one.err;
  const std::string serial = verify_json();
  EXPECT_EQ(progress(one.err), counted(kPairs)) << one.err;

  const CliRun many = run_penumbra("verify '" + lib().string() + "' -j 3");
  ASSERT_EQ(many.exit_code, 0) << many.out << many.err;
  EXPECT_EQ(verify_json(), serial);
  EXPECT_EQ(many.out, one.out);  // every check's line, in the same order
  EXPECT_EQ(progress(many.err), counted(kPairs)) << many.err;

  const CliRun quiet = run_penumbra("verify '" + lib().string() + "' -q");
  ASSERT_EQ(quiet.exit_code, 0) << quiet.out << quiet.err;
  EXPECT_EQ(verify_json(), serial);
  EXPECT_THAT(quiet.err, Not(HasSubstr("[1/")));
  EXPECT_THAT(quiet.out, Not(HasSubstr("PASS")));
  EXPECT_THAT(quiet.out, HasSubstr(" passed, 0 failed\n"));
}

// Device threads each with their own devices (Wine's runtimes drawing on two
// at once among them), against one: the same results, lines and progress.
TEST_F(Jobs, VerifyGivesTheSameResultsForAnyNumberOfDeviceThreads) {
  const CliRun one = run_penumbra("verify '" + lib().string() + "' -j 2 --device-threads 1");
  ASSERT_EQ(one.exit_code, 0) << one.out << one.err;
  const std::string single = verify_json();
  const CliRun many = run_penumbra("verify '" + lib().string() + "' -j 2 --device-threads 3");
  ASSERT_EQ(many.exit_code, 0) << many.out << many.err;
  EXPECT_EQ(verify_json(), single);
  EXPECT_EQ(many.out, one.out);
  EXPECT_EQ(progress(many.err), counted(kPairs)) << many.err;

  const CliRun none = run_penumbra("verify '" + lib().string() + "' --device-threads 0");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_THAT(none.err, HasSubstr("--device-threads"));
}

// verify's default (GALLIVM_PERF=nopt on lavapipe and llvmpipe) against
// --optimized-jit, the drivers' own default: byte for byte the same.
TEST_F(Jobs, VerifyGivesTheSameResultsWithTheShaderJitOptimizedOrNot) {
  const std::string unset = "env -u GALLIVM_PERF";  // whatever the suite's environment sets
  const CliRun fast = run_penumbra("verify '" + lib().string() + "' -q", unset);
  ASSERT_EQ(fast.exit_code, 0) << fast.out << fast.err;
  const std::string unoptimized = verify_json();
  const CliRun optimized =
      run_penumbra("verify '" + lib().string() + "' -q --optimized-jit", unset);
  ASSERT_EQ(optimized.exit_code, 0) << optimized.out << optimized.err;
  EXPECT_EQ(verify_json(), unoptimized);
  EXPECT_EQ(optimized.out, fast.out);
}

TEST_F(Jobs, ReportWritesTheSameFilesForAnyNumberOfJobs) {
  const CliRun one =
      run_penumbra("report '" + lib().string() + "' --jobs 1 -o " + path("report-1"));
  ASSERT_EQ(one.exit_code, 0) << one.out << one.err;
  EXPECT_EQ(progress(one.err), counted(kPictureRuns)) << one.err;
  const CliRun many = run_penumbra("report '" + lib().string() + "' -j 3 -o " + path("report-3"));
  ASSERT_EQ(many.exit_code, 0) << many.out << many.err;
  EXPECT_THAT(many.err, Not(HasSubstr("Warning"))) << "more jobs than cores are not an error";
  EXPECT_EQ(progress(many.err), counted(kPictureRuns)) << many.err;

  const auto serial = untimed_report_files(read_tree(dir_->path() / "report-1"));
  const auto parallel = untimed_report_files(read_tree(dir_->path() / "report-3"));
  ASSERT_EQ(parallel.size(), serial.size());
  for (const auto& [name, bytes] : serial) {
    ASSERT_TRUE(parallel.contains(name)) << name;
    EXPECT_TRUE(parallel.at(name) == bytes) << name << " differs";
  }

  const CliRun quiet = run_penumbra("report '" + lib().string() + "' -q -o " + path("report-q"));
  ASSERT_EQ(quiet.exit_code, 0) << quiet.out << quiet.err;
  EXPECT_TRUE(progress(quiet.err).empty()) << quiet.err;
}

}  // namespace
}  // namespace penumbra::testing
