// A recursive-descent reader for the subset of XML that JUnit reports use.
// It is strict (a report that a CI server would reject is rejected here) and
// bounded (nesting depth), since it reads files handed over from other machines.
#include <cstdint>

#include "penumbra/support/xml.hpp"

namespace penumbra {
namespace {

constexpr int kMaxDepth = 64;

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

bool is_name_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':' ||
         static_cast<std::uint8_t>(c) >= 0x80;
}

bool is_name_char(char c) {
  return is_name_start(c) || (c >= '0' && c <= '9') || c == '-' || c == '.';
}

void append_utf8(std::string& out, std::uint32_t code) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

class Reader {
 public:
  Reader(std::string_view text, const std::string& where) : text_(text), where_(where) {}

  Result<XmlElement> document() {
    if (starts("\xEF\xBB\xBF")) pos_ += 3;
    PENUMBRA_TRY(skip_misc());
    if (starts("<!DOCTYPE")) return error("a DOCTYPE is not allowed");
    if (!starts("<")) return error("expected the root element");
    auto root = parse_element(0);
    if (!root) return root.error();
    PENUMBRA_TRY(skip_misc());
    if (pos_ != text_.size()) return error("content after the root element");
    return root;
  }

 private:
  // "where:LINE:COL: message" for the current position.
  Error error(const std::string& message) const {
    std::size_t line = 1;
    std::size_t column = 1;
    for (std::size_t i = 0; i < pos_ && i < text_.size(); ++i) {
      column = text_[i] == '\n' ? 1 : column + 1;
      line += text_[i] == '\n' ? 1 : 0;
    }
    return make_error(Error::Kind::bad_input,
                      where_ + ":" + std::to_string(line) + ":" + std::to_string(column),
                      "not well-formed XML: " + message);
  }

  bool starts(std::string_view prefix) const { return text_.substr(pos_).starts_with(prefix); }
  bool at_end() const { return pos_ >= text_.size(); }

  void skip_space() {
    while (!at_end() && is_space(text_[pos_])) ++pos_;
  }

  // Moves past `end`, which must follow.
  Status skip_past(std::string_view end, const std::string& what) {
    const std::size_t found = text_.find(end, pos_);
    if (found == std::string_view::npos)
      return error(what + " is not closed by " + std::string(end));
    pos_ = found + end.size();
    return {};
  }

  // Whitespace, comments and processing instructions (the XML declaration).
  Status skip_misc() {
    for (;;) {
      skip_space();
      if (starts("<!--")) {
        PENUMBRA_TRY(skip_past("-->", "a comment"));
      } else if (starts("<?")) {
        PENUMBRA_TRY(skip_past("?>", "a processing instruction"));
      } else {
        return {};
      }
    }
  }

  Result<std::string> parse_name() {
    if (at_end() || !is_name_start(text_[pos_])) return error("expected a name");
    const std::size_t start = pos_;
    while (!at_end() && is_name_char(text_[pos_])) ++pos_;
    return std::string(text_.substr(start, pos_ - start));
  }

  // At '&': one entity or character reference, appended to `out`.
  Status parse_reference(std::string& out) {
    const std::size_t end = text_.find(';', pos_);
    if (end == std::string_view::npos || end - pos_ > 12) return error("'&' outside a reference");
    const std::string_view ref = text_.substr(pos_ + 1, end - pos_ - 1);
    static constexpr std::pair<std::string_view, char> kEntities[] = {
        {"lt", '<'}, {"gt", '>'}, {"amp", '&'}, {"quot", '"'}, {"apos", '\''}};
    for (const auto& [entity, c] : kEntities) {
      if (ref == entity) {
        out += c;
        pos_ = end + 1;
        return {};
      }
    }
    if (!ref.starts_with("#") || ref.size() < 2)
      return error("unknown entity &" + std::string(ref) + ";");
    const bool hex = ref[1] == 'x';
    const std::string_view digits = ref.substr(hex ? 2 : 1);
    std::uint32_t code = 0;
    for (char c : digits) {
      int digit = -1;
      if (c >= '0' && c <= '9') digit = c - '0';
      if (hex && c >= 'a' && c <= 'f') digit = c - 'a' + 10;
      if (hex && c >= 'A' && c <= 'F') digit = c - 'A' + 10;
      if (digit < 0) return error("bad character reference &" + std::string(ref) + ";");
      code = code * (hex ? 16u : 10u) + static_cast<std::uint32_t>(digit);
      if (code > 0x10FFFF)
        return error("character reference &" + std::string(ref) + "; is out of range");
    }
    const bool allowed = code == 0x9 || code == 0xA || code == 0xD ||
                         (code >= 0x20 && code <= 0xD7FF) || (code >= 0xE000 && code <= 0xFFFD) ||
                         (code >= 0x10000 && code <= 0x10FFFF);
    if (digits.empty() || !allowed) {
      return error("character reference &" + std::string(ref) + "; is not an XML character");
    }
    append_utf8(out, code);
    pos_ = end + 1;
    return {};
  }

  Result<std::string> parse_attribute_value() {
    if (at_end() || (text_[pos_] != '"' && text_[pos_] != '\'')) {
      return error("expected a quoted attribute value");
    }
    const char quote = text_[pos_++];
    std::string value;
    for (;;) {
      if (at_end()) return error("attribute value is not closed");
      const char c = text_[pos_];
      if (c == quote) break;
      if (c == '<') return error("'<' in an attribute value");
      if (c == '&') {
        PENUMBRA_TRY(parse_reference(value));
        continue;
      }
      // Literal whitespace in a value reads as a space (attribute-value normalization).
      value += is_space(c) ? ' ' : c;
      ++pos_;
    }
    ++pos_;
    return value;
  }

  Status parse_attributes(XmlElement& element) {
    for (;;) {
      const std::size_t before = pos_;
      skip_space();
      if (at_end() || text_[pos_] == '>' || starts("/>")) return {};
      if (pos_ == before) return error("expected whitespace before an attribute");
      auto key = parse_name();
      if (!key) return key.error();
      skip_space();
      if (at_end() || text_[pos_] != '=') return error("expected '=' after " + *key);
      ++pos_;
      skip_space();
      auto value = parse_attribute_value();
      if (!value) return value.error();
      if (element.attribute(*key)) return error("attribute " + *key + " given twice");
      element.attributes.emplace_back(std::move(*key), std::move(*value));
    }
  }

  // At '<' of a start tag.
  Result<XmlElement> parse_element(int depth) {
    if (depth >= kMaxDepth)
      return error("elements nested deeper than " + std::to_string(kMaxDepth));
    ++pos_;
    XmlElement element;
    PENUMBRA_TRY_ASSIGN(element.name, parse_name());
    PENUMBRA_TRY(parse_attributes(element));
    if (at_end()) return error("start tag <" + element.name + "> is not closed");
    if (starts("/>")) {
      pos_ += 2;
      return element;
    }
    ++pos_;
    PENUMBRA_TRY(parse_content(element, depth));
    bool blank = true;
    for (char c : element.text) blank = blank && is_space(c);
    if (blank && !element.children.empty()) element.text.clear();
    return element;
  }

  // Up to and past the end tag of `element`.
  Status parse_content(XmlElement& element, int depth) {
    for (;;) {
      if (at_end()) return error("element <" + element.name + "> is not closed");
      if (starts("</")) {
        pos_ += 2;
        auto end = parse_name();
        if (!end) return end.error();
        if (*end != element.name) {
          return error("end tag </" + *end + "> does not match <" + element.name + ">");
        }
        skip_space();
        if (at_end() || text_[pos_] != '>') return error("end tag </" + *end + "> is not closed");
        ++pos_;
        return {};
      }
      if (starts("<![CDATA[")) {
        const std::size_t start = pos_ + 9;
        PENUMBRA_TRY(skip_past("]]>", "a CDATA section"));
        element.text.append(text_.substr(start, pos_ - 3 - start));
      } else if (starts("<!--")) {
        PENUMBRA_TRY(skip_past("-->", "a comment"));
      } else if (starts("<?")) {
        PENUMBRA_TRY(skip_past("?>", "a processing instruction"));
      } else if (starts("<")) {
        auto child = parse_element(depth + 1);
        if (!child) return child.error();
        element.children.push_back(std::move(*child));
      } else if (text_[pos_] == '&') {
        PENUMBRA_TRY(parse_reference(element.text));
      } else {
        element.text += text_[pos_++];
      }
    }
  }

  std::string_view text_;
  const std::string& where_;
  std::size_t pos_ = 0;
};

}  // namespace

const std::string* XmlElement::attribute(std::string_view key) const {
  for (const auto& [k, value] : attributes) {
    if (k == key) return &value;
  }
  return nullptr;
}

Result<XmlElement> parse_xml(std::string_view text, const std::string& where) {
  return Reader(text, where).document();
}

}  // namespace penumbra
