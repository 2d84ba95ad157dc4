// JUnit XML reports as CI test views read them (GitLab, Jenkins, GitHub
// Actions reporters): <testsuites> of <testsuite>s of <testcase>s, and the
// merge of the reports of a sharded run (`penumbra verify --junit`,
// `penumbra junit-merge`).
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "penumbra/support/result.hpp"
#include "penumbra/support/shard.hpp"

namespace penumbra::cli {

// The <property> naming the shard ("I/N") a report of penumbra's covers.
inline constexpr std::string_view kJunitShardProperty = "penumbra.shard";

struct JunitCase {
  enum class Outcome { passed, failed, skipped };
  std::string classname;  // the group in a CI view
  std::string name;
  double seconds = 0.0;
  Outcome outcome = Outcome::passed;
  std::string message;  // failed or skipped: why, one line
  std::string details;  // failed: more text, shown under the message
};

struct JunitSuite {
  std::string name;
  std::vector<std::pair<std::string, std::string>> properties;  // name, value
  double seconds = 0.0;                                         // wall time of the whole suite
  std::vector<JunitCase> cases;

  // The value of the property `key`, or nullptr.
  const std::string* property(std::string_view key) const;
};

struct JunitReport {
  std::string name;
  std::vector<JunitSuite> suites;

  bool failed() const;  // a case failed, or none passed
};

// The UTF-8 XML document, with tests/failures/errors/skipped/time counted on
// every suite and on the whole. Bytes that XML 1.0 cannot carry (control
// characters other than tab, newline and carriage return, invalid UTF-8)
// become U+FFFD.
std::string to_junit_xml(const JunitReport& report);

// Reads a document to_junit_xml() wrote (any <testsuites> of <testsuite>s
// of <testcase>s, or one <testsuite>; <error> reads as a failure). Errors
// (bad_input) name `where`, with a line and column for XML that is not
// well-formed.
Result<JunitReport> parse_junit_xml(std::string_view text, const std::string& where);

// The reports of one sharded run, each with its file name, as one report:
// every suite, ordered by shard. Each report must carry kJunitShardProperty;
// together they must be shards 1..N of one N, each once, with no testcase
// (classname and name) in two of them. Errors (bad_input) name the file and
// what is allowed.
Result<JunitReport> merge_junit_shards(
    const std::vector<std::pair<std::string, JunitReport>>& reports);

}  // namespace penumbra::cli
