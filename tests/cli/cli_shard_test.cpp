// `penumbra verify --shard I/N --junit FILE` through the binary: the shards
// of a small library add up to the whole run, check for check, and the JUnit
// reports merge into it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <pugixml.hpp>

#include "cli_harness.hpp"
#include "junit.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::testing {
namespace {

using cli::JunitCase;
using cli::JunitSuite;
using cli::parse_junit_xml;
using ::testing::HasSubstr;

// Three targets (one with the GL path, one with the bytecode path) and a
// min-max technique, so that depth and min-max mip checks fall in several
// shards.
constexpr const char* kManifest = R"({
  "schema": 1,
  "targets": ["spirv", "glsl330", "hlsl_dx9"],
  "sets": [
    {"technique": ["hard"]},
    {"technique": ["pcf_grid"], "kernel": [3]},
    {"technique": ["minmax_pcf"], "kernel": [8]}
  ]})";

constexpr int kShards = 3;

// Each check (classname, name) with its outcome.
using Checks = std::map<std::pair<std::string, std::string>, JunitCase::Outcome>;

class ShardedVerify : public EvalFixture {
 protected:
  static void SetUpTestSuite() { set_up_eval("shard", kManifest); }
  static void TearDownTestSuite() { tear_down_eval(); }

  static std::string verify_args(const std::string& extra) {
    return "verify '" + lib().string() + "' " + extra;
  }
  static std::string text(const std::string& name) {
    auto bytes = read_file(dir_->path() / name);
    return bytes ? *bytes : "";
  }
  // The testcases of a report, each once.
  static Checks checks(const std::string& name) {
    Checks all;
    auto report = parse_junit_xml(text(name), name);
    EXPECT_TRUE(report.ok()) << report.error().to_string();
    if (!report) return all;
    for (const JunitSuite& suite : report->suites) {
      for (const JunitCase& c : suite.cases) {
        EXPECT_TRUE(all.emplace(std::pair(c.classname, c.name), c.outcome).second)
            << name << ": " << c.classname << " " << c.name << " twice";
      }
    }
    return all;
  }
};

// One test for the whole run and its shards: each test runs in a process of
// its own, and verify is the slow part.
TEST_F(ShardedVerify, ShardsAddUpToTheWholeRunAndMergeIntoIt) {
  const CliRun whole_run = run_penumbra(verify_args("--junit " + path("whole.xml")));
  ASSERT_EQ(whole_run.exit_code, 0) << whole_run.out << whole_run.err;
  const Checks whole = checks("whole.xml");
  std::string shard_files;
  Checks united;
  for (int i = 1; i <= kShards; ++i) {
    const std::string shard = std::to_string(i) + "/" + std::to_string(kShards);
    const std::string file = "s" + std::to_string(i) + ".xml";
    const CliRun run = run_penumbra(verify_args("--shard " + shard + " --junit " + path(file)));
    ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
    EXPECT_THAT(run.out, HasSubstr("shard " + shard + ": "));
    EXPECT_THAT(text("lib/verify.json"), HasSubstr("\"shard\": \"" + shard + "\""));
    const Checks part = checks(file);
    EXPECT_GT(part.size(), 0u) << shard;
    for (const auto& [check, outcome] : part) {
      EXPECT_TRUE(united.emplace(check, outcome).second)
          << check.first << " " << check.second << " in two shards";
    }
    shard_files = path(file) + " " + shard_files;  // given to the merge in reverse order
  }
  EXPECT_EQ(united, whole);
  // Every kind of check took part.
  for (const std::string classname :
       {"depth_pass", "minmax_mip", "function_form", "hard", "pcf_grid_k3", "minmax_pcf_k8"}) {
    EXPECT_TRUE(std::any_of(whole.begin(), whole.end(), [&](const auto& c) {
      return c.first.first == classname;
    })) << classname;
  }
  EXPECT_TRUE(whole.contains({"hard", "hlsl_dx9/vulkan/steps"}));
  EXPECT_TRUE(whole.contains({"depth_pass", "glsl330/steps"}));

  const CliRun merge = run_penumbra("junit-merge " + shard_files + "-o " + path("merged.xml"));
  ASSERT_EQ(merge.exit_code, 0) << merge.out << merge.err;
  EXPECT_EQ(checks("merged.xml"), whole);

  // The report as a CI server reads it: counts that add up, every testcase
  // named and timed, the shard as a property.
  const std::string whole_xml = text("whole.xml");
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(whole_xml.c_str()));
  const pugi::xml_node root = doc.document_element();
  ASSERT_STREQ(root.name(), "testsuites");
  const pugi::xml_node suite = root.child("testsuite");
  ASSERT_TRUE(suite);
  EXPECT_FALSE(suite.next_sibling());
  std::size_t cases = 0;
  std::size_t skipped = 0;
  bool shard_property = false;
  for (const pugi::xml_node child : suite.children()) {
    if (std::string_view(child.name()) == "properties") {
      for (const pugi::xml_node property : child.children()) {
        shard_property =
            shard_property ||
            (std::string_view(property.attribute("name").value()) == "penumbra.shard" &&
             std::string_view(property.attribute("value").value()) == "1/1");
      }
      continue;
    }
    ASSERT_STREQ(child.name(), "testcase");
    ++cases;
    ASSERT_TRUE(child.attribute("classname"));
    ASSERT_TRUE(child.attribute("name"));
    ASSERT_TRUE(child.attribute("time"));
    for (const pugi::xml_node outcome : child.children()) {
      EXPECT_STREQ(outcome.name(), "skipped") << child.attribute("name").value();
      ++skipped;
    }
  }
  EXPECT_EQ(cases, whole.size());
  EXPECT_TRUE(shard_property);
  for (const pugi::xml_node counted : {root, suite}) {
    EXPECT_EQ(counted.attribute("tests").value(), std::to_string(cases));
    EXPECT_STREQ(counted.attribute("failures").value(), "0");
    EXPECT_EQ(counted.attribute("skipped").value(), std::to_string(skipped));
  }
}

TEST_F(ShardedVerify, AFailedCheckIsAJunitFailureAndFailsTheMerge) {
  const auto broken = dir_->path() / "broken";
  std::filesystem::copy(lib(), broken, std::filesystem::copy_options::recursive);
  std::ofstream(broken / "hlsl_dx9" / "hard" / "query.frag.hlsl") << "float4 main( : oops\n";
  const std::string args =
      "verify '" + broken.string() + "' --variant hard --target hlsl_dx9 --no-gl";
  // hard (variant 0) with hlsl_dx9 (target 6) is in shard (0 + 6) mod 2 + 1 = 1.
  const CliRun one = run_penumbra(args + " --shard 1/2 --junit " + path("b1.xml"));
  EXPECT_EQ(one.exit_code, 1) << one.out << one.err;
  EXPECT_THAT(text("b1.xml"), HasSubstr("<failure message="));
  // Shard 2 has nothing to run: it passes, and the merge judges the whole.
  const CliRun two = run_penumbra(args + " --shard 2/2 --junit " + path("b2.xml"));
  EXPECT_EQ(two.exit_code, 0) << two.out << two.err;
  EXPECT_THAT(text("b2.xml"), HasSubstr("tests=\"0\""));
  const CliRun merge =
      run_penumbra("junit-merge " + path("b1.xml") + " " + path("b2.xml") + " -o " + path("b.xml"));
  EXPECT_EQ(merge.exit_code, 1) << merge.out << merge.err;
  EXPECT_THAT(merge.out, HasSubstr("FAIL hard hlsl_dx9/vulkan"));
}

// Checked before anything runs: exit 2, one message, the previous outputs
// left as they were.
TEST(VerifyShardArguments, BadShardOrJunitIsExit2AndLeavesOutputsAlone) {
  const ScratchDir dir("shard-args");
  dir.write("keep.xml", "previous");
  std::filesystem::create_directory(dir.path() / "lib");
  dir.write("lib/verify.json", "previous");
  const std::string lib = "'" + (dir.path() / "lib").string() + "'";
  const std::string keep = " --junit '" + (dir.path() / "keep.xml").string() + "'";
  const std::pair<std::string, std::string> cases[] = {
      {"--shard 3/2" + keep, "penumbra: error: --shard 3/2: I must be in 1..N (1..2)"},
      {"--shard 0/2" + keep, "penumbra: error: --shard 0/2: expected I/N"},
      {"--shard 2" + keep, "penumbra: error: --shard 2: expected I/N"},
      {"--shard 1/0" + keep, "penumbra: error: --shard 1/0: expected I/N"},
      {"--junit '" + (dir.path() / "no/such.xml").string() + "'",
       "allowed: a file in an existing directory"},
      {"--junit " + lib, "is a directory"},
  };
  for (const auto& [flags, message] : cases) {
    const CliRun run = run_penumbra("verify " + lib + " " + flags);
    EXPECT_EQ(run.exit_code, 2) << flags << ": " << run.out << run.err;
    EXPECT_THAT(run.err, HasSubstr(message)) << flags;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_EQ(run.out, "");
    auto kept = read_file(dir.path() / "keep.xml");
    EXPECT_EQ(kept ? *kept : "", "previous");
    auto json = read_file(dir.path() / "lib" / "verify.json");
    EXPECT_EQ(json ? *json : "", "previous");
  }
}

}  // namespace
}  // namespace penumbra::testing
