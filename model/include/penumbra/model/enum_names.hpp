// A model enum's names, as its to_string() gives them, read back and listed
// for messages: what parse_map_encoding(), parse_map_layout() and
// parse_depth_format() share.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace penumbra {

// The member of `all` whose to_string() is `name`, or none.
template <typename Enum, std::size_t N>
std::optional<Enum> parse_enum(const Enum (&all)[N], std::string_view name) {
  for (const Enum value : all) {
    if (to_string(value) == name) return value;
  }
  return std::nullopt;
}

// "a, b, c": every member's to_string(), in `all`'s order.
template <typename Enum, std::size_t N>
std::string enum_names(const Enum (&all)[N]) {
  std::string out;
  for (const Enum value : all) out += (out.empty() ? "" : ", ") + std::string(to_string(value));
  return out;
}

}  // namespace penumbra
