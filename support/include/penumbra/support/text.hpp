// Small string helpers for names and messages.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace penumbra {

// `text` with a-z / A-Z changed case; every other byte as it is.
std::string ascii_upper(std::string_view text);
std::string ascii_lower(std::string_view text);

// The items with `separator` between them: join({"a", "b"}, ", ") is "a, b".
std::string join(std::span<const std::string_view> items, std::string_view separator);

}  // namespace penumbra
