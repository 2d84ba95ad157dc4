// A selector is either an index or part of a name, never both: an all-digit
// selector is never searched for in the names, so "0" cannot pick a device
// whose name happens to contain a zero.
#include "penumbra/support/device_selector.hpp"

#include <algorithm>
#include <cctype>

#include "penumbra/support/text.hpp"

namespace penumbra {
namespace {

bool all_digits(std::string_view text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); });
}

}  // namespace

std::optional<std::size_t> match_selector(std::span<const std::string> names,
                                          std::string_view selector) {
  if (all_digits(selector)) {
    // Over-long digit strings are out of range, not an overflow.
    if (selector.size() >= 10) return std::nullopt;
    const std::size_t index = std::stoul(std::string(selector));
    if (index < names.size()) return index;
    return std::nullopt;
  }
  const std::string lower_selector = ascii_lower(selector);
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (ascii_lower(names[i]).find(lower_selector) != std::string::npos) return i;
  }
  return std::nullopt;
}

std::string list_choices(std::span<const std::string> names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    text += (i ? ", " : "") + std::to_string(i) + ": " + names[i];
  }
  return text;
}

}  // namespace penumbra
