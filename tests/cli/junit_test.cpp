#include "junit.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace penumbra::cli {
namespace {

using ::testing::HasSubstr;
using Outcome = JunitCase::Outcome;

JunitReport shard_report(int index, int count, std::vector<JunitCase> cases) {
  const std::string shard = std::to_string(index) + "/" + std::to_string(count);
  return {"penumbra verify",
          {{"shard " + shard, {{std::string(kJunitShardProperty), shard}}, 1.5, std::move(cases)}}};
}

TEST(Junit, WritesCountsAndReadsBackEveryOutcome) {
  const JunitReport report =
      shard_report(1, 1,
                   {{"hard", "spirv/vulkan/steps", 0.25, Outcome::passed, "", ""},
                    {"hard", "glsl450/gl", 0.0, Outcome::skipped, "no EGL", ""},
                    {"pcss", "hlsl_dx9/vulkan", 1.0, Outcome::failed, "compile: <oops> & \"so\"",
                     "line 1\nline 2"}});
  const std::string xml = to_junit_xml(report);
  EXPECT_THAT(xml, HasSubstr("<testsuites name=\"penumbra verify\" tests=\"3\" failures=\"1\" "
                             "errors=\"0\" skipped=\"1\" time=\"1.500\">"));
  EXPECT_THAT(
      xml, HasSubstr("<testcase classname=\"hard\" name=\"spirv/vulkan/steps\" time=\"0.250\" />"));
  EXPECT_THAT(xml, HasSubstr("<skipped message=\"no EGL\" />"));
  EXPECT_THAT(xml, HasSubstr("<property name=\"penumbra.shard\" value=\"1/1\" />"));
  auto back = parse_junit_xml(xml, "r.xml");
  ASSERT_TRUE(back.ok()) << back.error().to_string();
  ASSERT_EQ(back->suites.size(), 1u);
  const JunitSuite& suite = back->suites[0];
  EXPECT_EQ(*suite.property(kJunitShardProperty), "1/1");
  ASSERT_EQ(suite.cases.size(), 3u);
  EXPECT_EQ(suite.cases[0].outcome, Outcome::passed);
  EXPECT_DOUBLE_EQ(suite.cases[0].seconds, 0.25);
  EXPECT_EQ(suite.cases[1].outcome, Outcome::skipped);
  EXPECT_EQ(suite.cases[1].message, "no EGL");
  EXPECT_EQ(suite.cases[2].outcome, Outcome::failed);
  EXPECT_EQ(suite.cases[2].message, "compile: <oops> & \"so\"");
  EXPECT_EQ(suite.cases[2].details, "line 1\nline 2");
  EXPECT_TRUE(back->failed());
  EXPECT_EQ(to_junit_xml(*back), xml);
}

TEST(Junit, EscapesWhatItWritesAndReadsItBack) {
  const std::string awkward = "a < b && c > \"d\" 'e'\n\ttab";
  const JunitReport report =
      shard_report(1, 1, {{awkward, awkward, 0, Outcome::failed, awkward, awkward}});
  const std::string xml = to_junit_xml(report);
  EXPECT_THAT(xml, HasSubstr("message=\"a &lt; b &amp;&amp; c > &quot;d&quot; 'e'&#10;&#09;tab\""));
  EXPECT_THAT(xml, HasSubstr(">a &lt; b &amp;&amp; c &gt; \"d\" 'e'\n\ttab</failure>"));
  auto back = parse_junit_xml(xml, "r.xml");
  ASSERT_TRUE(back.ok()) << back.error().to_string();
  const JunitCase& c = back->suites.at(0).cases.at(0);
  EXPECT_EQ(c.classname, awkward);
  EXPECT_EQ(c.message, awkward);
  EXPECT_EQ(c.details, awkward);
}

TEST(Junit, ReplacesWhatXmlCannotCarry) {
  const std::string bad = std::string("bell\x07 nul") + '\0' + " cut\xC3 end \xF0\x9F\x98\x80";
  const std::string xml =
      to_junit_xml(shard_report(1, 1, {{"a", "b", 0, Outcome::failed, bad, bad}}));
  auto back = parse_junit_xml(xml, "r.xml");
  ASSERT_TRUE(back.ok()) << back.error().to_string();
  const std::string expected =
      "bell\xEF\xBF\xBD nul\xEF\xBF\xBD cut\xEF\xBF\xBD end \xF0\x9F\x98\x80";
  EXPECT_EQ(back->suites.at(0).cases.at(0).message, expected);
  EXPECT_EQ(back->suites.at(0).cases.at(0).details, expected);
}

TEST(Junit, ReadsCommentsCdataReferencesAndSingleQuotes) {
  auto report = parse_junit_xml(
      "\xEF\xBB\xBF<?xml version='1.0'?>\n<!-- c --><testsuite name='s &#x41;&#66;'>"
      "<?pi?><!-- in --><testcase name='t'><failure message='m'>x<![CDATA[<raw>&]]>y</failure>"
      "</testcase></testsuite>\n",
      "r.xml");
  ASSERT_TRUE(report.ok()) << report.error().to_string();
  ASSERT_EQ(report->suites.size(), 1u);
  EXPECT_EQ(report->suites[0].name, "s AB");
  ASSERT_EQ(report->suites[0].cases.size(), 1u);
  EXPECT_EQ(report->suites[0].cases[0].outcome, Outcome::failed);
  EXPECT_EQ(report->suites[0].cases[0].details, "x<raw>&y");
}

TEST(Junit, RejectsWhatIsNotWellFormedWithItsPlace) {
  for (const char* text : {"", "<testsuites>", "<testsuites></testsuite>", "<a x=1/>",
                           "<testsuites/><testsuites/>", "\n  <1/>"}) {
    auto report = parse_junit_xml(text, "doc.xml");
    ASSERT_FALSE(report.ok()) << text;
    EXPECT_EQ(report.error().kind, Error::Kind::bad_input);
    EXPECT_THAT(report.error().message, ::testing::StartsWith("not well-formed XML: ")) << text;
    EXPECT_THAT(report.error().message, HasSubstr("; allowed: a JUnit XML report")) << text;
    EXPECT_THAT(report.error().where, ::testing::StartsWith("doc.xml:")) << text;
  }
  // At the second root's name.
  EXPECT_EQ(parse_junit_xml("<testsuites/>\n<b/>", "doc.xml").error().to_string(),
            "doc.xml:2:2: not well-formed XML: content after the root element; allowed: a JUnit "
            "XML report");
  std::string deep;
  for (int i = 0; i < 100000; ++i) deep += "<a>";
  EXPECT_FALSE(parse_junit_xml(deep, "deep.xml").ok());
}

TEST(Junit, NothingPassedIsAFailure) {
  EXPECT_TRUE(shard_report(1, 1, {}).failed());
  EXPECT_TRUE(shard_report(1, 1, {{"a", "b", 0, Outcome::skipped, "", ""}}).failed());
  EXPECT_FALSE(shard_report(1, 1, {{"a", "b", 0, Outcome::passed, "", ""}}).failed());
}

TEST(Junit, RejectsOtherDocuments) {
  auto html = parse_junit_xml("<html/>", "page.xml");
  ASSERT_FALSE(html.ok());
  EXPECT_EQ(html.error().to_string(),
            "page.xml: not a JUnit report: the root element is <html>; allowed: <testsuites> of "
            "<testsuite>s of <testcase>s");
  auto time = parse_junit_xml("<testsuite><testcase name='a' time='soon'/></testsuite>", "t.xml");
  ASSERT_FALSE(time.ok());
  EXPECT_THAT(time.error().message, HasSubstr("time=\"soon\""));
  EXPECT_FALSE(
      parse_junit_xml("<testsuites><testsuite><testcase/></testsuite></testsuites>", "n.xml").ok());
}

std::vector<std::pair<std::string, JunitReport>> shards(
    std::vector<std::pair<std::string, JunitReport>> reports) {
  return reports;
}

TEST(Junit, MergesEveryShardInOrder) {
  auto merged = merge_junit_shards(shards({
      {"b.xml", shard_report(2, 2, {{"hard", "spirv/vulkan/b", 0, Outcome::failed, "off", ""}})},
      {"a.xml", shard_report(1, 2, {{"hard", "spirv/vulkan/a", 0, Outcome::passed, "", ""}})},
  }));
  ASSERT_TRUE(merged.ok()) << merged.error().to_string();
  ASSERT_EQ(merged->suites.size(), 2u);
  EXPECT_EQ(merged->suites[0].cases[0].name, "spirv/vulkan/a");
  EXPECT_EQ(merged->suites[1].cases[0].name, "spirv/vulkan/b");
  EXPECT_TRUE(merged->failed());
}

TEST(Junit, MergeRejectsShardsThatDoNotAddUp) {
  const JunitCase a{"hard", "a", 0, Outcome::passed, "", ""};
  const JunitCase b{"hard", "b", 0, Outcome::passed, "", ""};
  const std::pair<std::vector<std::pair<std::string, JunitReport>>, std::string> cases[] = {
      {{{"a.xml", shard_report(1, 2, {a})}, {"b.xml", shard_report(1, 2, {b})}},
       "b.xml: shard 1/2 is also in a.xml; allowed: each shard once"},
      {{{"a.xml", shard_report(1, 2, {a})}, {"b.xml", shard_report(2, 2, {a})}},
       "b.xml: testcase hard a is also in a.xml; allowed: shards that do not overlap"},
      {{{"a.xml", shard_report(1, 2, {a})}, {"b.xml", shard_report(2, 3, {b})}},
       "b.xml: shard 2/3 but a.xml is shard 1/2; allowed: shards of one N"},
      {{{"a.xml", shard_report(1, 3, {a})}, {"b.xml", shard_report(3, 3, {b})}},
       "junit-merge: missing shard 2/3; allowed: every shard 1..3 of the run, each once"},
      {{{"a.xml", JunitReport{"x", {{"s", {}, 0, {a}}}}}},
       "a.xml: no <property name=\"penumbra.shard\">; allowed: reports written by penumbra "
       "verify --junit"},
      {{{"a.xml", shard_report(3, 2, {a})}},
       "a.xml: property penumbra.shard 3/2: I must be in 1..N (1..2)"},
  };
  for (const auto& [reports, message] : cases) {
    auto merged = merge_junit_shards(reports);
    ASSERT_FALSE(merged.ok()) << message;
    EXPECT_EQ(merged.error().kind, Error::Kind::bad_input);
    EXPECT_EQ(merged.error().to_string(), message);
  }
}

}  // namespace
}  // namespace penumbra::cli
