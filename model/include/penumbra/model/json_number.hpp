// Checked reads of JSON numbers into C++ arithmetic types.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>
#include <utility>

#include "penumbra/support/text.hpp"

namespace penumbra {

// `value` as a T, thrown as nlohmann's out_of_range (which names its place)
// when it is no number or does not fit. nlohmann's own get<T>() of 3e117 as
// an unsigned, or of 1e39 as a float, is undefined behaviour. Integer types
// take integers only; true and false are no numbers.
template <typename T>
T number_as(const nlohmann::json& value) {
  static_assert(std::is_arithmetic_v<T> && !std::is_same_v<T, bool>, "a number type");
  if constexpr (std::is_integral_v<T>) {
    if (value.is_number_unsigned()) {
      const std::uint64_t u = value.get<std::uint64_t>();
      if (std::in_range<T>(u)) return static_cast<T>(u);
    } else if (value.is_number_integer()) {
      const std::int64_t i = value.get<std::int64_t>();
      if (std::in_range<T>(i)) return static_cast<T>(i);
    }
  } else if (value.is_number()) {
    const double d = value.get<double>();
    if (std::abs(d) <= static_cast<double>(std::numeric_limits<T>::max())) {
      return static_cast<T>(d);
    }
  }
  throw nlohmann::json::out_of_range::create(
      406, shorten(value.dump()) + " is not a number that fits its field", &value);
}

// `j`'s member `key` read by number_as().
template <typename T>
void number_at(const nlohmann::json& j, const char* key, T& out) {
  out = number_as<T>(j.at(key));
}

}  // namespace penumbra
