#include "penumbra/model/json_text.hpp"

#include <string_view>

#include "penumbra/support/text.hpp"

namespace penumbra {

std::string describe_json(const nlohmann::json& value) {
  if (value.is_object()) return "an object";
  if (value.is_array()) return "an array";
  return shorten(value.dump());
}

// A parse error ends "...; last read: '<the token>'", and the token can be a
// whole unterminated 10 MB string.
std::string json_exception_text(const nlohmann::json::exception& e) {
  std::string_view what = e.what();
  if (const auto end = what.find("] "); end != std::string_view::npos) what.remove_prefix(end + 2);
  constexpr std::string_view kLastRead = "last read: '";
  const auto token = what.find(kLastRead);
  if (token == std::string_view::npos) return shorten(what, 400);
  const std::size_t start = token + kLastRead.size();
  std::string_view rest = what.substr(start);
  if (rest.ends_with('\'')) rest.remove_suffix(1);
  return std::string(what.substr(0, start)) + shorten(rest, 40) + "'";
}

}  // namespace penumbra
