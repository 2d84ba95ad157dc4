// `penumbra junit-merge` through the binary on hand-written shard reports:
// what it merges, its exit status, and the inputs it refuses (exit 2, one
// message naming the file, nothing written).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "cli_harness.hpp"
#include "junit.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::testing {
namespace {

using cli::kJunitShardProperty;
using cli::parse_junit_xml;
using ::testing::HasSubstr;

// A report as `penumbra verify --shard I/N --junit` writes it, with the
// testcases (classname, name, outcome) given as XML.
std::string shard_xml(const std::string& shard, const std::string& cases) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"penumbra verify\">\n"
         "<testsuite name=\"penumbra verify shard " +
         shard + "\" time=\"2.5\"><properties><property name=\"penumbra.shard\" value=\"" + shard +
         "\"/></properties>\n" + cases + "</testsuite></testsuites>\n";
}

const std::string kPassA =
    "<testcase classname=\"hard\" name=\"spirv/vulkan/steps\" time=\"0.5\"/>";
const std::string kPassB =
    "<testcase classname=\"depth_pass\" name=\"spirv/steps\" time=\"0.1\"/>"
    "<testcase classname=\"hard\" name=\"glsl330/gl\"><skipped message=\"no EGL\"/></testcase>";
const std::string kFailC =
    "<testcase classname=\"pcss\" name=\"hlsl_dx9/vulkan\" time=\"1\">"
    "<failure message=\"compile: glslang failed\">line 1&#10;line 2</failure></testcase>";

class JunitMerge : public ::testing::Test {
 protected:
  JunitMerge() : dir_("junit-merge") {}

  std::string file(const std::string& name) const {
    return "'" + (dir_.path() / name).string() + "'";
  }
  std::string out_text() const {
    auto text = read_file(dir_.path() / "out.xml");
    return text ? *text : "";
  }
  // Runs a merge into `out` that must be refused: exit 2, one error line
  // naming `where`, out.xml as it was.
  void expect_refused(const std::string& inputs, const std::string& where,
                      const std::string& message, const std::string& out = "out.xml") {
    dir_.write("out.xml", "previous");
    const CliRun run = run_penumbra("junit-merge " + inputs + " -o " + file(out));
    EXPECT_EQ(run.exit_code, 2) << run.out << run.err;
    EXPECT_EQ(run.out, "");
    EXPECT_THAT(run.err, HasSubstr("error: "));
    EXPECT_THAT(run.err, ::testing::StartsWith(where));
    EXPECT_THAT(run.err, HasSubstr(message));
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_EQ(out_text(), "previous");
  }

  ScratchDir dir_;
};

TEST_F(JunitMerge, WritesEveryShardsSuiteAndPassesWhenNothingFailed) {
  dir_.write("s1.xml", shard_xml("1/2", kPassA));
  dir_.write("s2.xml", shard_xml("2/2", kPassB));
  const CliRun run = run_penumbra("junit-merge " + file("s2.xml") + " " + file("s1.xml") + " -o " +
                                  file("out.xml"));
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_THAT(run.out, HasSubstr("2 passed, 0 failed, 1 skipped, from 2 shards"));
  auto merged = parse_junit_xml(out_text(), "out.xml");
  ASSERT_TRUE(merged.ok()) << merged.error().to_string();
  ASSERT_EQ(merged->suites.size(), 2u);
  EXPECT_EQ(*merged->suites[0].property(kJunitShardProperty), "1/2");  // in shard order
  EXPECT_EQ(merged->suites[1].cases.size(), 2u);
  EXPECT_THAT(out_text(),
              HasSubstr("tests=\"3\" failures=\"0\" errors=\"0\" skipped=\"1\" time=\"5.000\""));
}

TEST_F(JunitMerge, AFailedTestcaseIsExit1AndStillWritten) {
  dir_.write("s1.xml", shard_xml("1/2", kPassA));
  dir_.write("s2.xml", shard_xml("2/2", kFailC));
  const CliRun run = run_penumbra("junit-merge " + file("s1.xml") + " " + file("s2.xml") + " -o " +
                                  file("out.xml"));
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  EXPECT_THAT(run.out, HasSubstr("FAIL pcss hlsl_dx9/vulkan: compile: glslang failed"));
  EXPECT_THAT(out_text(),
              HasSubstr("<failure message=\"compile: glslang failed\">line 1\nline 2</failure>"));
}

TEST_F(JunitMerge, NothingPassedIsExit1) {
  dir_.write("s1.xml",
             shard_xml("1/1", "<testcase classname=\"a\" name=\"b\"><skipped/></testcase>"));
  const CliRun run = run_penumbra("junit-merge " + file("s1.xml") + " -o " + file("out.xml"));
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
}

TEST_F(JunitMerge, RefusesMissingUnreadableAndForeignFiles) {
  dir_.write("s1.xml", shard_xml("1/2", kPassA));
  dir_.write("s2.xml", shard_xml("2/2", kPassB));
  const std::string both = file("s1.xml") + " " + file("s2.xml");
  const std::string error = "penumbra: error: " + dir_.path().string() + "/";
  expect_refused(
      file("s1.xml") + " " + file("absent.xml"), error + "absent.xml",
      "cannot open the file: No such file or directory; allowed: each shard's penumbra verify "
      "--junit report");
  dir_.write("broken.xml", shard_xml("2/2", kPassB).substr(0, 120));
  expect_refused(file("s1.xml") + " " + file("broken.xml"),
                 dir_.path().string() + "/broken.xml:3:", "not well-formed XML");
  dir_.write("html.xml", "<html><body/></html>");
  expect_refused(file("html.xml"), error + "html.xml",
                 "not a JUnit report: the root element is <html>");
  dir_.write("plain.xml", "<testsuites><testsuite><testcase name=\"x\"/></testsuite></testsuites>");
  expect_refused(file("plain.xml"), error + "plain.xml",
                 "allowed: reports written by penumbra verify --junit");
  expect_refused(both, "penumbra: error: -o " + (dir_.path() / "no/such/dir.xml").string(),
                 "allowed: a file in an existing directory", "no/such/dir.xml");
}

TEST_F(JunitMerge, RefusesShardsThatDoNotAddUp) {
  dir_.write("s1.xml", shard_xml("1/3", kPassA));
  dir_.write("s2.xml", shard_xml("2/3", kPassB));
  dir_.write("s3.xml", shard_xml("3/3", kFailC));
  dir_.write("again.xml", shard_xml("2/3", kFailC));
  dir_.write("overlap.xml", shard_xml("3/3", kPassA));
  dir_.write("other_n.xml", shard_xml("3/4", kFailC));
  const std::string s12 = file("s1.xml") + " " + file("s2.xml") + " ";
  const std::string error = "penumbra: error: " + dir_.path().string() + "/";
  expect_refused(s12 + file("again.xml"), error + "again.xml", "shard 2/3 is also in");
  expect_refused(s12 + file("overlap.xml"), error + "overlap.xml",
                 "testcase hard spirv/vulkan/steps is also in");
  expect_refused(s12 + file("other_n.xml"), error + "other_n.xml", "allowed: shards of one N");
  expect_refused(s12, "penumbra: error: junit-merge: missing shard 3/3",
                 "allowed: every shard 1..3");
}

TEST_F(JunitMerge, NeedsReportsAndAnOutput) {
  dir_.write("s1.xml", shard_xml("1/1", kPassA));
  EXPECT_EQ(run_penumbra("junit-merge -o " + file("out.xml")).exit_code, 2);
  EXPECT_EQ(run_penumbra("junit-merge " + file("s1.xml")).exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(dir_.path() / "out.xml"));
}

}  // namespace
}  // namespace penumbra::testing
