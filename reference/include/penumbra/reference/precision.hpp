// How far a correct GPU result may be from the reference, and why: see
// docs/verification.md for the error model.
#pragma once

#include <cmath>

#include "penumbra/model/model.hpp"

namespace penumbra::reference {

struct SamplingPrecision {
  // Fractional bits of the GPU's texel coordinates (Vulkan's
  // subTexelPrecisionBits; lavapipe reports 8). At least 1.
  int sub_texel_bits = 8;

  // One step of the GPU's texel coordinates, 2^-bits texels.
  double step() const { return std::ldexp(1.0, -sub_texel_bits); }
  // Half-width, in texels, of the window around a texel boundary inside
  // which a point sample may read either neighbour.
  double point_window() const { return step() + 1e-6; }
};

// Largest |GPU - reference| allowed for a technique's non-ambiguous pixels.
double tolerance(Technique technique, const SamplingPrecision& precision);

}  // namespace penumbra::reference
