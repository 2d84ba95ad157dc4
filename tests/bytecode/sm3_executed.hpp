// The most instructions a Shader Model 3 program in vkd3d-compiler's
// d3d-asm can execute. vkd3d writes every loop as `rep i#` with 255
// iterations and leaves by `break`, so the trip counts come from the source:
// the caller gives one per loop in the order the loops open.
#pragma once

#include <string_view>
#include <vector>

#include "penumbra/support/result.hpp"

namespace penumbra::testing {

// Every executed instruction counts its slots (sm3_slots.cpp), flow control
// included: `if` takes its longer arm, a loop runs its body `trips` times.
// An error when the loops are not as many as `trips` or nest badly.
Result<long long> sm3_most_executed(std::string_view assembly, const std::vector<long long>& trips);

}  // namespace penumbra::testing
