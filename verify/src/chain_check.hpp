// screen_blur's decomposed checks after the factor (docs/runtime.md, "The
// screen_blur chain"): a GPU image against the CPU's step applied to the
// GPU's own previous image.
#pragma once

#include "penumbra/verify/verify.hpp"

namespace penumbra {

// Compares every channel of every pixel; a bad_input Error when the images'
// sizes or channel counts differ.
Result<ChainCheck> check_chain(const FloatImage& gpu, const FloatImage& cpu, double tolerance,
                               std::string_view what);

}  // namespace penumbra
