#include "validators.hpp"

#include <charconv>
#include <cstdint>

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

void refuse_empty_values(CLI::App& app) {
  for (CLI::App* command : app.get_subcommands({})) {
    for (CLI::Option* option : command->get_options()) {
      if (option->get_type_size() != 0) option->check(non_empty());
    }
  }
}

}  // namespace penumbra::cli
