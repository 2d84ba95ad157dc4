#include "glsl/preprocess_memo.hpp"

#include <algorithm>
#include <cctype>

#include "penumbra/support/content_hash.hpp"

namespace penumbra {
namespace {

bool starts_name(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool in_name(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

std::string_view trim_left(std::string_view line) {
  const std::size_t start = line.find_first_not_of(" \t");
  return start == std::string_view::npos ? std::string_view() : line.substr(start);
}

// The macro a "#define NAME..." line defines, and the rest of the line;
// nullopt for any other line.
std::optional<std::pair<std::string_view, std::string_view>> define_of(std::string_view line) {
  line = trim_left(line);
  if (!line.starts_with('#')) return std::nullopt;
  line = trim_left(line.substr(1));
  if (!line.starts_with("define")) return std::nullopt;
  line = trim_left(line.substr(6));
  std::size_t end = 0;
  while (end < line.size() && in_name(line[end])) ++end;
  if (end == 0) return std::nullopt;
  return std::pair{line.substr(0, end), line.substr(end)};
}

template <class Each>
void for_each_line(std::string_view text, Each each) {
  while (!text.empty()) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    each(text.substr(0, end));
    text.remove_prefix(std::min(end + 1, text.size()));
  }
}

// What a header's lines can bring into a preprocess besides its defines'
// names: their values and every other line's names.
void add_header_identifiers(std::string_view header, std::set<std::string>& out) {
  for_each_line(header, [&](std::string_view line) {
    if (trim_left(line).starts_with("//")) return;
    const auto define = define_of(line);
    out.merge(identifiers_of(define ? define->second : line));
  });
}

std::string text_key(ShaderStage stage, const std::string& source, const std::string& header) {
  ContentHash key;
  key.add(to_string(stage)).add(source).add(header);
  return key.hex();
}

}  // namespace

std::set<std::string> identifiers_of(std::string_view text) {
  std::set<std::string> out;
  for (std::size_t i = 0; i < text.size();) {
    if (!starts_name(text[i])) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && in_name(text[end])) ++end;
    out.emplace(text.substr(i, end - i));
    i = end;
  }
  return out;
}

std::string header_key(std::string_view header, const std::set<std::string>& mentioned) {
  std::string out;
  for_each_line(header, [&](std::string_view line) {
    const auto define = define_of(line);
    const bool blank = trim_left(line).starts_with("//") ||
                       (define && !mentioned.contains(std::string(define->first)));
    if (!blank) out += line;
    out += '\n';
  });
  return out;
}

std::optional<Preprocessed> PreprocessMemo::find(ShaderStage stage, const std::string& source,
                                                 const std::string& header) const {
  const std::scoped_lock lock(mutex_);
  const auto mentioned = mentioned_.find({stage, source});
  if (mentioned == mentioned_.end()) return std::nullopt;
  const std::string key = text_key(stage, source, header_key(header, mentioned->second.names));
  const auto found = std::ranges::find(texts_, key, &decltype(texts_)::value_type::first);
  if (found == texts_.end()) return std::nullopt;
  return found->second;
}

void PreprocessMemo::add(ShaderStage stage, const std::string& source, const std::string& header,
                         const Preprocessed& made) {
  const std::scoped_lock lock(mutex_);
  Mentioned& mentioned = mentioned_[{stage, source}];
  for (const std::string& path : made.inputs) {
    if (!mentioned.files.insert(path).second) continue;
    const std::set<std::string>& names = file_identifiers(path);
    mentioned.names.insert(names.begin(), names.end());
  }
  add_header_identifiers(header, mentioned.names);
  texts_.emplace_back(text_key(stage, source, header_key(header, mentioned.names)), made);
  if (texts_.size() > capacity_) texts_.pop_front();
}

const std::set<std::string>& PreprocessMemo::file_identifiers(const std::string& path) {
  auto found = files_.find(path);
  if (found == files_.end()) {
    found = files_.emplace(path, identifiers_of(shaderlib_.read(path).value_or(""))).first;
  }
  return found->second;
}

}  // namespace penumbra
