// Argument checks whose messages name the argument (CLI11 prefixes it) and
// what is allowed, in a few characters: no echo of a long value.
#pragma once

#include <CLI/CLI.hpp>

namespace penumbra::cli {

// Refuses "" ("empty; allowed: ..."): given to every option that takes a value.
CLI::Validator non_empty();

// A seed: a decimal integer in 0..2^64-1, so "-1" does not wrap around.
CLI::Validator seed_value();

// Adds non_empty() to every option of `app`'s subcommands that takes a value.
void refuse_empty_values(CLI::App& app);

}  // namespace penumbra::cli
