// The counts on <testsuite> and <testsuites> are derived, never stored: a
// report read back and written again always adds up.
#include "penumbra/support/junit.hpp"

#include <algorithm>
#include <charconv>

#include "penumbra/support/xml.hpp"

namespace penumbra {
namespace {

std::string seconds_text(double seconds) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, std::max(0.0, seconds),
                                    std::chars_format::fixed, 3);
  return std::string(buffer, result.ptr);
}

struct Counts {
  std::size_t tests = 0;
  std::size_t failures = 0;
  std::size_t skipped = 0;
  double seconds = 0.0;
};

void add_counts(Counts& counts, const JunitSuite& suite) {
  counts.tests += suite.cases.size();
  for (const JunitCase& c : suite.cases) {
    counts.failures += c.outcome == JunitCase::Outcome::failed ? 1 : 0;
    counts.skipped += c.outcome == JunitCase::Outcome::skipped ? 1 : 0;
  }
  counts.seconds += suite.seconds;
}

void set_counts(XmlElement& element, const Counts& counts) {
  element.attributes.emplace_back("tests", std::to_string(counts.tests));
  element.attributes.emplace_back("failures", std::to_string(counts.failures));
  element.attributes.emplace_back("errors", "0");
  element.attributes.emplace_back("skipped", std::to_string(counts.skipped));
  element.attributes.emplace_back("time", seconds_text(counts.seconds));
}

XmlElement case_xml(const JunitCase& c) {
  XmlElement element{
      "testcase",
      {{"classname", c.classname}, {"name", c.name}, {"time", seconds_text(c.seconds)}},
      "",
      {}};
  if (c.outcome == JunitCase::Outcome::failed) {
    element.children.push_back({"failure", {{"message", c.message}}, c.details, {}});
  } else if (c.outcome == JunitCase::Outcome::skipped) {
    element.children.push_back({"skipped", {{"message", c.message}}, "", {}});
  }
  return element;
}

XmlElement suite_xml(const JunitSuite& suite) {
  XmlElement element{"testsuite", {{"name", suite.name}}, "", {}};
  Counts counts;
  add_counts(counts, suite);
  set_counts(element, counts);
  if (!suite.properties.empty()) {
    XmlElement properties{"properties", {}, "", {}};
    for (const auto& [key, value] : suite.properties) {
      properties.children.push_back({"property", {{"name", key}, {"value", value}}, "", {}});
    }
    element.children.push_back(std::move(properties));
  }
  for (const JunitCase& c : suite.cases) element.children.push_back(case_xml(c));
  return element;
}

Error not_junit(const std::string& where, const std::string& message) {
  return make_error(
      Error::Kind::bad_input, where,
      "not a JUnit report: " + message + "; allowed: <testsuites> of <testsuite>s of <testcase>s");
}

Result<double> parse_seconds(const XmlElement& element, const std::string& where) {
  const std::string* text = element.attribute("time");
  if (!text) return 0.0;
  double seconds = 0.0;
  const auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), seconds);
  if (ec != std::errc() || end != text->data() + text->size() || !(seconds >= 0.0)) {
    return not_junit(where,
                     "<" + element.name + "> time=\"" + *text + "\" is not a number of seconds");
  }
  return seconds;
}

Result<JunitCase> parse_case(const XmlElement& element, const std::string& where) {
  JunitCase c;
  const std::string* classname = element.attribute("classname");
  const std::string* name = element.attribute("name");
  if (!name) return not_junit(where, "a <testcase> without a name");
  c.classname = classname ? *classname : "";
  c.name = *name;
  PENUMBRA_TRY_ASSIGN(c.seconds, parse_seconds(element, where));
  for (const XmlElement& child : element.children) {
    const std::string* message = child.attribute("message");
    if (child.name == "failure" || child.name == "error") {
      c.outcome = JunitCase::Outcome::failed;
    } else if (child.name == "skipped" && c.outcome != JunitCase::Outcome::failed) {
      c.outcome = JunitCase::Outcome::skipped;
    } else {
      continue;  // system-out, system-err, properties
    }
    c.message = message ? *message : "";
    c.details = child.text;
  }
  return c;
}

Result<JunitSuite> parse_suite(const XmlElement& element, const std::string& where) {
  JunitSuite suite;
  const std::string* name = element.attribute("name");
  suite.name = name ? *name : "";
  PENUMBRA_TRY_ASSIGN(suite.seconds, parse_seconds(element, where));
  for (const XmlElement& child : element.children) {
    if (child.name == "testcase") {
      auto c = parse_case(child, where);
      if (!c) return c.error();
      suite.cases.push_back(std::move(*c));
    } else if (child.name == "properties") {
      for (const XmlElement& property : child.children) {
        const std::string* key = property.attribute("name");
        const std::string* value = property.attribute("value");
        if (property.name != "property" || !key || !value) {
          return not_junit(where, "<properties> holds other than <property name value>");
        }
        suite.properties.emplace_back(*key, *value);
      }
    } else if (child.name == "testsuite") {
      return not_junit(where, "nested <testsuite>");
    }
  }
  return suite;
}

}  // namespace

const std::string* JunitSuite::property(std::string_view key) const {
  for (const auto& [k, value] : properties) {
    if (k == key) return &value;
  }
  return nullptr;
}

bool JunitReport::failed() const {
  bool passed = false;
  for (const JunitSuite& suite : suites) {
    for (const JunitCase& c : suite.cases) {
      if (c.outcome == JunitCase::Outcome::failed) return true;
      passed = passed || c.outcome == JunitCase::Outcome::passed;
    }
  }
  return !passed;
}

std::string to_junit_xml(const JunitReport& report) {
  XmlElement root{"testsuites", {{"name", report.name}}, "", {}};
  Counts counts;
  for (const JunitSuite& suite : report.suites) {
    add_counts(counts, suite);
    root.children.push_back(suite_xml(suite));
  }
  set_counts(root, counts);
  return to_xml(root);
}

Result<JunitReport> parse_junit_xml(std::string_view text, const std::string& where) {
  auto root = parse_xml(text, where);
  if (!root) {
    return make_error(root.error().kind, root.error().where,
                      root.error().message + "; allowed: a JUnit XML report");
  }
  JunitReport report;
  if (root->name == "testsuite") {
    auto suite = parse_suite(*root, where);
    if (!suite) return suite.error();
    report.suites.push_back(std::move(*suite));
    return report;
  }
  if (root->name != "testsuites")
    return not_junit(where, "the root element is <" + root->name + ">");
  const std::string* name = root->attribute("name");
  report.name = name ? *name : "";
  for (const XmlElement& child : root->children) {
    if (child.name != "testsuite") continue;
    auto suite = parse_suite(child, where);
    if (!suite) return suite.error();
    report.suites.push_back(std::move(*suite));
  }
  return report;
}

}  // namespace penumbra
