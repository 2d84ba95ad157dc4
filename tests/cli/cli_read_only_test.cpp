// A library penumbra cannot write into (a read-only checkout, an installed
// share/ folder, a CI artifact): verify still runs and prints its results,
// writes verify.json only where --results says, and leaves the library as
// it was; report names -o before drawing anything.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_harness.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::testing {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

constexpr const char* kManifest =
    R"({"schema": 1, "targets": ["spirv"], "sets": [{"technique": "hard"}]})";

class ReadOnlyLibrary : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto manifest = dir.write("m.json", kManifest);
    const CliRun built =
        run_penumbra("build -q --no-cache '" + manifest.string() + "' -o '" + lib().string() + "'");
    ASSERT_EQ(built.exit_code, 0) << built.err;
  }
  fs::path lib() const { return dir.path() / "lib"; }
  std::string verify(const std::string& extra) const {
    return "verify '" + lib().string() + "' --no-wine --no-gl " + extra;
  }

  ScratchDir dir{"read-only"};
};

TEST_F(ReadOnlyLibrary, VerifyPrintsItsResultsAndSaysVerifyJsonWasNotWritten) {
  const auto before = read_tree(lib());
  const ReadOnlyDir read_only(lib());
  if (!read_only.ok()) GTEST_SKIP() << "cannot make a folder read-only here";
  const CliRun run = run_penumbra(verify(""));
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_THAT(run.out, HasSubstr("PASS hard [spirv]"));
  EXPECT_THAT(run.out, HasSubstr(" passed, 0 failed"));
  EXPECT_THAT(run.out,
              HasSubstr("verify.json not written: " + lib().string() + " cannot be written into"));
  EXPECT_THAT(run.out, HasSubstr("pass --results FILE"));
  EXPECT_THAT(run.err, HasSubstr("note: verify.json will not be written"));
  EXPECT_FALSE(fs::exists(lib() / "verify.json"));
  EXPECT_TRUE(read_tree(lib()) == before) << "the library changed";
}

TEST_F(ReadOnlyLibrary, VerifyWritesItsResultsWhereResultsSays) {
  const auto results = dir.path() / "results" / "verify.json";
  fs::create_directories(results.parent_path());
  const ReadOnlyDir read_only(lib());
  if (!read_only.ok()) GTEST_SKIP() << "cannot make a folder read-only here";
  const CliRun run = run_penumbra(verify("-q --results '" + results.string() + "'"));
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_THAT(run.out, HasSubstr("results: " + results.string()));
  EXPECT_THAT(run.out, Not(HasSubstr("not written")));
  EXPECT_THAT(run.err, Not(HasSubstr("note:")));
  auto text = read_file(results);
  ASSERT_TRUE(text.ok());
  const auto json = nlohmann::json::parse(*text, nullptr, false);
  ASSERT_FALSE(json.is_discarded());
  ASSERT_TRUE(json.contains("variants"));
  EXPECT_EQ(json["variants"].size(), 1u);
  EXPECT_FALSE(fs::exists(lib() / "verify.json"));
}

// The report is files, not lines: it goes elsewhere or nowhere, refused
// before the device (here one that does not exist) is opened.
TEST_F(ReadOnlyLibrary, ReportNamesOutputOptionBeforeAnyWork) {
  const auto before = read_tree(lib());
  const ReadOnlyDir read_only(lib());
  if (!read_only.ok()) GTEST_SKIP() << "cannot make a folder read-only here";
  const CliRun run =
      run_penumbra("report '" + lib().string() + "' --no-wine --device no-such-device-anywhere");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_THAT(run.err, HasSubstr((lib() / "report").string()));
  EXPECT_THAT(run.err, HasSubstr("pass -o DIR"));
  EXPECT_TRUE(read_tree(lib()) == before) << "the library changed";
}

}  // namespace
}  // namespace penumbra::testing
