// How far a long run (verify, the report's pictures) has got, told to a
// caller-given consumer as each unit of work finishes.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace penumbra {

struct Progress {
  std::size_t done = 0;   // units finished, this one included
  std::size_t total = 0;  // units the run has
  double seconds = 0.0;   // since the run began
  std::string unit;       // the one just finished, e.g. "pcss_b16_p16_poisson [glsl450]"
};

// Called once per unit, one call at a time, from whichever thread finished it.
using ProgressConsumer = std::function<void(const Progress&)>;

}  // namespace penumbra
