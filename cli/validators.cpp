#include "validators.hpp"

#include <cerrno>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "penumbra/support/text.hpp"

namespace penumbra::cli {

CLI::Validator non_empty() {
  return CLI::Validator(
      [](std::string& value) {
        return value.empty() ? std::string("empty; allowed: a non-empty value") : std::string();
      },
      "", "NON_EMPTY");
}

CLI::Validator seed_value() {
  return CLI::Validator(
      [](std::string& value) {
        std::uint64_t seed = 0;
        const char* end = value.data() + value.size();
        const auto [stop, error] = std::from_chars(value.data(), end, seed);
        if (value.empty() || error != std::errc() || stop != end) {
          return "seed " + shorten(value, 40) + " is out of range; allowed 0..18446744073709551615";
        }
        return std::string();
      },
      "", "SEED");
}

CLI::Validator positive_number() {
  // CLI::PositiveNumber's message prints its range with std::to_string.
  return CLI::Validator(
      [](std::string& value) {
        char* end = nullptr;
        errno = 0;
        const double number = std::strtod(value.c_str(), &end);
        const bool parsed = !value.empty() && end == value.c_str() + value.size() && errno == 0;
        if (parsed && std::isfinite(number) && number > 0) return std::string();
        return "value " + shorten(value, 40) + " is out of range; allowed a number in " +
               short_number(DBL_MIN) + ".." + short_number(DBL_MAX);
      },
      "POSITIVE", "POSITIVE");
}

void refuse_empty_values(CLI::App& app) {
  for (CLI::App* command : app.get_subcommands({})) {
    for (CLI::Option* option : command->get_options()) {
      if (option->get_type_size() != 0) option->check(non_empty());
    }
  }
}

}  // namespace penumbra::cli
