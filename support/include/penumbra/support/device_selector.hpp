// Picking one of a list of named devices by a user's selector (both engines'
// `device` option), and listing the choices when none matches.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace penumbra {

// All digits: that index, if in range. Anything else: the first name that
// contains `selector`, ignoring case. Empty when nothing matches.
std::optional<std::size_t> match_selector(std::span<const std::string> names,
                                          std::string_view selector);

// "0: first, 1: second, ..." ("" for no names), for an error to list.
std::string list_choices(std::span<const std::string> names);

}  // namespace penumbra
