// Comparing a GPU visibility image with the reference (docs/verification.md).
#pragma once

#include <cstddef>
#include <nlohmann/json_fwd.hpp>

#include "penumbra/support/image.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::reference {

// At most this fraction of a run's pixels may be ambiguous, or the run fails:
// more means the inputs are degenerate and check too little.
inline constexpr double kMaxAmbiguousFraction = 0.02;

struct Comparison {
  std::size_t pixels = 0;          // all pixels
  std::size_t compared = 0;        // pixels not ambiguous
  std::size_t ambiguous = 0;       // pixels excluded by the ambiguity mask
  std::size_t over_tolerance = 0;  // compared pixels with |gpu - ref| > tolerance (or NaN)
  double max_abs_error = 0.0;      // over compared pixels; infinity for a NaN
  double mean_abs_error = 0.0;     // over compared pixels
  double tolerance = 0.0;
  bool pass =
      false;  // compared > 0, over_tolerance == 0, ambiguous <= kMaxAmbiguousFraction * pixels
};

// Compares channel 0 of `gpu` and `reference` pixel by pixel, skipping the
// pixels where `ambiguous` is non-zero. The three images must have one size.
Result<Comparison> compare(const FloatImage& gpu, const FloatImage& reference,
                           const FloatImage& ambiguous, double tolerance);

void to_json(nlohmann::json& json, const Comparison& comparison);

}  // namespace penumbra::reference
