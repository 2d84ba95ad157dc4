// Small string helpers for names and messages.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace penumbra {

// `text` with a-z / A-Z changed case; every other byte as it is.
std::string ascii_upper(std::string_view text);
std::string ascii_lower(std::string_view text);

// The items with `separator` between them: join({"a", "b"}, ", ") is "a, b".
std::string join(std::span<const std::string_view> items, std::string_view separator);

// Text quoted in a message: `text` itself when at most `max_bytes` long, else
// its first bytes (whole UTF-8 characters) and "…", so a 10 MB value is not
// echoed whole.
std::string shorten(std::string_view text, std::size_t max_bytes = 80);

// `value` as %g writes it: "1.79769e+308", not DBL_MAX's 309 digits.
std::string short_number(double value);

}  // namespace penumbra
