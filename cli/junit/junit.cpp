// The counts on <testsuite> and <testsuites> are derived, never stored: a
// report read back and written again always adds up. pugixml parses,
// escapes and indents; what no escaping makes well-formed (invalid UTF-8,
// control characters: compilers' and drivers' messages can carry anything)
// is replaced before it, since CI servers reject a whole report over one
// stray byte.
#include "junit.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <pugixml.hpp>
#include <sstream>

namespace penumbra::cli {
namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD

// The length of the well-formed UTF-8 sequence at `text[at]` that XML 1.0
// allows, or 0.
std::size_t xml_char_length(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<std::uint8_t>(text[at + i]); };
  const std::uint8_t lead = byte(0);
  if (lead < 0x80) return lead >= 0x20 || lead == '\t' || lead == '\n' || lead == '\r' ? 1 : 0;
  std::size_t length = 0;
  std::uint32_t code = 0;
  if ((lead & 0xE0) == 0xC0) {
    length = 2;
    code = lead & 0x1F;
  } else if ((lead & 0xF0) == 0xE0) {
    length = 3;
    code = lead & 0x0F;
  } else if ((lead & 0xF8) == 0xF0) {
    length = 4;
    code = lead & 0x07;
  } else {
    return 0;
  }
  if (at + length > text.size()) return 0;
  for (std::size_t i = 1; i < length; ++i) {
    if ((byte(i) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(i) & 0x3F);
  }
  static constexpr std::uint32_t kSmallest[] = {0, 0, 0x80, 0x800, 0x10000};
  const bool valid = code >= kSmallest[length] && code <= 0x10FFFF &&
                     !(code >= 0xD800 && code <= 0xDFFF) && code != 0xFFFE && code != 0xFFFF;
  return valid ? length : 0;
}

// `text` with each byte XML cannot carry replaced by U+FFFD.
std::string xml_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t length = xml_char_length(text, at);
    if (length == 0) {
      out += kReplacement;
      ++at;
    } else {
      out.append(text.substr(at, length));
      at += length;
    }
  }
  return out;
}

void set(pugi::xml_node element, const char* key, std::string_view value) {
  const std::string text = xml_text(value);
  element.append_attribute(key).set_value(text.c_str(), text.size());
}

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

void set_counts(pugi::xml_node element, const Counts& counts) {
  set(element, "tests", std::to_string(counts.tests));
  set(element, "failures", std::to_string(counts.failures));
  set(element, "errors", "0");
  set(element, "skipped", std::to_string(counts.skipped));
  set(element, "time", seconds_text(counts.seconds));
}

void append_case(pugi::xml_node parent, const JunitCase& c) {
  pugi::xml_node element = parent.append_child("testcase");
  set(element, "classname", c.classname);
  set(element, "name", c.name);
  set(element, "time", seconds_text(c.seconds));
  if (c.outcome == JunitCase::Outcome::failed) {
    pugi::xml_node failure = element.append_child("failure");
    set(failure, "message", c.message);
    if (!c.details.empty()) failure.text().set(xml_text(c.details).c_str());
  } else if (c.outcome == JunitCase::Outcome::skipped) {
    set(element.append_child("skipped"), "message", c.message);
  }
}

void append_suite(pugi::xml_node parent, const JunitSuite& suite) {
  pugi::xml_node element = parent.append_child("testsuite");
  set(element, "name", suite.name);
  Counts counts;
  add_counts(counts, suite);
  set_counts(element, counts);
  if (!suite.properties.empty()) {
    pugi::xml_node properties = element.append_child("properties");
    for (const auto& [key, value] : suite.properties) {
      pugi::xml_node property = properties.append_child("property");
      set(property, "name", key);
      set(property, "value", value);
    }
  }
  for (const JunitCase& c : suite.cases) append_case(element, c);
}

Error not_junit(const std::string& where, const std::string& message) {
  return make_error(
      Error::Kind::bad_input, where,
      "not a JUnit report: " + message + "; allowed: <testsuites> of <testsuite>s of <testcase>s");
}

// An error at "where:LINE:COL", the place of the byte at `offset` (pugixml's
// offsets) in `text`.
Error not_well_formed(std::string_view text, std::ptrdiff_t offset, const std::string& where,
                      const std::string& message) {
  const std::string_view before =
      text.substr(0, static_cast<std::size_t>(std::max(std::ptrdiff_t{0}, offset)));
  const std::size_t line_start = before.rfind('\n') + 1;  // npos + 1 == 0
  const auto line = std::count(before.begin(), before.end(), '\n') + 1;
  return make_error(
      Error::Kind::bad_input,
      where + ":" + std::to_string(line) + ":" + std::to_string(before.size() - line_start + 1),
      "not well-formed XML: " + message + "; allowed: a JUnit XML report");
}

std::string_view name_of(pugi::xml_node element) {
  return element.name();
}

// The value of the attribute `key`, or nullptr when `element` has none.
const char* attribute(pugi::xml_node element, const char* key) {
  const pugi::xml_attribute attr = element.attribute(key);
  return attr ? attr.value() : nullptr;
}

// The character data (text and CDATA sections) right inside `element`.
std::string text_of(pugi::xml_node element) {
  std::string text;
  for (pugi::xml_node child : element.children()) {
    if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata)
      text += child.value();
  }
  return text;
}

Result<double> parse_seconds(pugi::xml_node element, const std::string& where) {
  const char* text = attribute(element, "time");
  if (!text) return 0.0;
  const std::string_view value = text;
  double seconds = 0.0;
  const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), seconds);
  if (ec != std::errc() || end != value.data() + value.size() || !(seconds >= 0.0)) {
    return not_junit(where, "<" + std::string(name_of(element)) + "> time=\"" + std::string(value) +
                                "\" is not a number of seconds");
  }
  return seconds;
}

Result<JunitCase> parse_case(pugi::xml_node element, const std::string& where) {
  JunitCase c;
  const char* classname = attribute(element, "classname");
  const char* name = attribute(element, "name");
  if (!name) return not_junit(where, "a <testcase> without a name");
  c.classname = classname ? classname : "";
  c.name = name;
  PENUMBRA_TRY_ASSIGN(c.seconds, parse_seconds(element, where));
  for (pugi::xml_node child : element.children()) {
    if (name_of(child) == "failure" || name_of(child) == "error") {
      c.outcome = JunitCase::Outcome::failed;
    } else if (name_of(child) == "skipped" && c.outcome != JunitCase::Outcome::failed) {
      c.outcome = JunitCase::Outcome::skipped;
    } else {
      continue;  // system-out, system-err, properties
    }
    const char* message = attribute(child, "message");
    c.message = message ? message : "";
    c.details = text_of(child);
  }
  return c;
}

Result<JunitSuite> parse_suite(pugi::xml_node element, const std::string& where) {
  JunitSuite suite;
  const char* name = attribute(element, "name");
  suite.name = name ? name : "";
  PENUMBRA_TRY_ASSIGN(suite.seconds, parse_seconds(element, where));
  for (pugi::xml_node child : element.children()) {
    if (name_of(child) == "testcase") {
      auto c = parse_case(child, where);
      if (!c) return c.error();
      suite.cases.push_back(std::move(*c));
    } else if (name_of(child) == "properties") {
      for (pugi::xml_node property : child.children()) {
        if (property.type() != pugi::node_element) continue;
        const char* key = attribute(property, "name");
        const char* value = attribute(property, "value");
        if (name_of(property) != "property" || !key || !value) {
          return not_junit(where, "<properties> holds other than <property name value>");
        }
        suite.properties.emplace_back(key, value);
      }
    } else if (name_of(child) == "testsuite") {
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
  pugi::xml_document doc;
  pugi::xml_node declaration = doc.append_child(pugi::node_declaration);
  set(declaration, "version", "1.0");
  set(declaration, "encoding", "UTF-8");
  pugi::xml_node root = doc.append_child("testsuites");
  set(root, "name", report.name);
  Counts counts;
  for (const JunitSuite& suite : report.suites) add_counts(counts, suite);
  set_counts(root, counts);
  for (const JunitSuite& suite : report.suites) append_suite(root, suite);
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_indent, pugi::encoding_utf8);
  return out.str();
}

Result<JunitReport> parse_junit_xml(std::string_view text, const std::string& where) {
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed =
      doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!parsed) {
    std::string message = parsed.description();
    if (!message.empty()) message[0] = static_cast<char>(std::tolower(message[0]));
    return not_well_formed(text, parsed.offset, where, message);
  }
  // pugixml reads a fragment of several elements; a document has one.
  const pugi::xml_node root = doc.document_element();
  for (pugi::xml_node next = root.next_sibling(); next; next = next.next_sibling()) {
    if (next.type() == pugi::node_element) {
      return not_well_formed(text, next.offset_debug(), where, "content after the root element");
    }
  }
  JunitReport report;
  if (name_of(root) == "testsuite") {
    auto suite = parse_suite(root, where);
    if (!suite) return suite.error();
    report.suites.push_back(std::move(*suite));
    return report;
  }
  if (name_of(root) != "testsuites") {
    return not_junit(where, "the root element is <" + std::string(name_of(root)) + ">");
  }
  const char* name = attribute(root, "name");
  report.name = name ? name : "";
  for (pugi::xml_node child : root.children("testsuite")) {
    auto suite = parse_suite(child, where);
    if (!suite) return suite.error();
    report.suites.push_back(std::move(*suite));
  }
  return report;
}

}  // namespace penumbra::cli
