// One of N disjoint slices of a job, numbered from 1 as CI matrices number
// their jobs (`--shard I/N`).
#pragma once

#include <string>
#include <string_view>

#include "penumbra/support/result.hpp"

namespace penumbra {

struct Shard {
  int index = 1;  // I, 1 <= I <= count
  int count = 1;  // N >= 1; 1/1 is the whole job

  bool operator==(const Shard&) const = default;
};

// Parses "I/N"; an error (bad_input) at "`argument` `text`" says what is allowed.
Result<Shard> parse_shard(std::string_view text, const std::string& argument);

// "I/N".
std::string to_string(Shard shard);

}  // namespace penumbra
