// A minimal XML element tree: enough to write JUnit reports and to read back
// the ones penumbra wrote. Elements, attributes and text; no DTDs, no
// namespaces.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "penumbra/support/result.hpp"

namespace penumbra {

struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;  // in document order
  std::string text;  // character data inside; whitespace-only data beside children is dropped
  std::vector<XmlElement> children;

  // The attribute's value, or nullptr when the element has none of that name.
  const std::string* attribute(std::string_view key) const;
};

// A UTF-8 document: the XML declaration, then `root` with each child on its
// own line, indented by two spaces a level. Text and attribute values are
// escaped; bytes XML 1.0 cannot carry (control characters other than tab,
// newline and carriage return, invalid UTF-8) become U+FFFD.
std::string to_xml(const XmlElement& root);

// Parses a document of one root element. Accepts the XML declaration,
// comments, processing instructions, CDATA sections, the five predefined
// entities and character references; rejects a DOCTYPE. Errors (bad_input)
// are located at "where:LINE:COL".
Result<XmlElement> parse_xml(std::string_view text, const std::string& where);

}  // namespace penumbra
