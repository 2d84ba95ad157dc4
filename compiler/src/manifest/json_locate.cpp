#include "manifest/json_locate.hpp"

#include <regex>
#include <string>
#include <vector>

namespace penumbra::manifest_detail {
namespace {

// A forward-only reader over well-formed JSON; every step fails (returns
// false) on anything unexpected instead of guessing.
class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  std::size_t offset() const { return pos_; }

  void skip_space() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' ||
                                   text_[pos_] == '\n' || text_[pos_] == '\r')) {
      ++pos_;
    }
  }
  bool peek(char c) {
    skip_space();
    return pos_ < text_.size() && text_[pos_] == c;
  }
  bool take(char c) {
    if (!peek(c)) return false;
    ++pos_;
    return true;
  }

  // A string token, unescaped (\uXXXX is kept verbatim: keys are compared
  // with RFC 6901 tokens, which manifests write in ASCII).
  bool string(std::string& out) {
    if (!take('"')) return false;
    out.clear();
    while (pos_ < text_.size()) {
      const char c = text_[pos_++];
      if (c == '"') return true;
      if (c != '\\') {
        out += c;
        continue;
      }
      if (pos_ >= text_.size()) return false;
      const char e = text_[pos_++];
      switch (e) {
        case 'n':
          out += '\n';
          break;
        case 't':
          out += '\t';
          break;
        case 'r':
          out += '\r';
          break;
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'u':
          out += "\\u";
          break;
        default:
          out += e;
      }
    }
    return false;
  }

  // Skips one value of any kind.
  bool skip_value() {
    skip_space();
    if (pos_ >= text_.size()) return false;
    std::string ignored;
    switch (text_[pos_]) {
      case '"':
        return string(ignored);
      case '{':
        ++pos_;
        if (take('}')) return true;
        do {
          if (!string(ignored) || !take(':') || !skip_value()) return false;
        } while (take(','));
        return take('}');
      case '[':
        ++pos_;
        if (take(']')) return true;
        do {
          if (!skip_value()) return false;
        } while (take(','));
        return take(']');
      default:  // number, true, false, null
        const std::size_t start = pos_;
        while (pos_ < text_.size() &&
               std::string_view(",]} \t\r\n").find(text_[pos_]) == std::string_view::npos) {
          ++pos_;
        }
        return pos_ > start;
    }
  }

  // Moves to the start of member `key` of the object here.
  bool enter_member(const std::string& key) {
    if (!take('{')) return false;
    if (peek('}')) return false;
    std::string name;
    do {
      if (!string(name) || !take(':')) return false;
      if (name == key) {
        skip_space();
        return true;
      }
      if (!skip_value()) return false;
    } while (take(','));
    return false;
  }

  // Moves to the start of element `index` of the array here.
  bool enter_element(std::size_t index) {
    if (!take('[')) return false;
    for (std::size_t i = 0; i < index; ++i) {
      if (!skip_value() || !take(',')) return false;
    }
    skip_space();
    return pos_ < text_.size() && text_[pos_] != ']';
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
};

// "/sets/0/a~1b" -> {"sets", "0", "a/b"}.
std::vector<std::string> pointer_tokens(std::string_view pointer) {
  std::vector<std::string> tokens;
  while (!pointer.empty() && pointer.front() == '/') {
    pointer.remove_prefix(1);
    const std::size_t end = pointer.find('/');
    std::string token;
    const std::string_view raw = pointer.substr(0, end);
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] == '~' && i + 1 < raw.size()) {
        token += raw[i + 1] == '1' ? '/' : '~';
        ++i;
      } else {
        token += raw[i];
      }
    }
    tokens.push_back(std::move(token));
    pointer.remove_prefix(end == std::string_view::npos ? pointer.size() : end);
  }
  return tokens;
}

}  // namespace

TextPosition position_of(std::string_view text, std::size_t offset) {
  TextPosition position;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++position.line;
      position.column = 1;
    } else {
      ++position.column;
    }
  }
  return position;
}

std::optional<TextPosition> locate_pointer(std::string_view text, std::string_view pointer) {
  Scanner scanner(text);
  scanner.skip_space();
  for (const std::string& token : pointer_tokens(pointer)) {
    if (scanner.peek('{')) {
      if (!scanner.enter_member(token)) return std::nullopt;
    } else if (scanner.peek('[')) {
      if (token.empty() || token.find_first_not_of("0123456789") != std::string::npos) {
        return std::nullopt;
      }
      if (!scanner.enter_element(std::stoul(token))) return std::nullopt;
    } else {
      return std::nullopt;
    }
  }
  return position_of(text, scanner.offset());
}

void add_position(Error& error, std::string_view text, std::string_view source) {
  if (!error.where.starts_with(source)) return;
  const std::string rest = error.where.substr(source.size());  // "" or ": /sets/1..."
  std::optional<TextPosition> position;
  static const std::regex kSyntax(R"(parse error at line ([0-9]+), column ([0-9]+))");
  std::smatch match;
  if (rest.empty() && std::regex_search(error.message, match, kSyntax)) {
    position = TextPosition{std::stoi(match[1]), std::stoi(match[2])};
  } else if (rest.starts_with(": /")) {
    // ": /sets/1/kernel", or ": /sets/1: variant x" from expansion.
    std::string_view pointer = std::string_view(rest).substr(2);
    position = locate_pointer(text, pointer.substr(0, pointer.find(':')));
  }
  if (!position) return;
  error.where = std::string(source) + ":" + std::to_string(position->line) + ":" +
                std::to_string(position->column) + rest;
}

}  // namespace penumbra::manifest_detail
