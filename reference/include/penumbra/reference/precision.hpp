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

  // Texels by which the shader's own float32 arithmetic may move a sample
  // before the GPU quantizes it, beyond the receiver's: an atlas tile's
  // placement (map_layout atlas); 0 for a map of its own.
  double coordinate_error = 0.0;

  // One step of the GPU's texel coordinates, 2^-bits texels.
  double step() const { return std::ldexp(1.0, -sub_texel_bits); }
  // How far, in texels, a sample's position on the GPU may lie from the
  // reference's: a step, and the shader's coordinate_error.
  double reach() const { return step() + coordinate_error; }
  // Half-width, in texels, of the window around a texel boundary inside
  // which a point sample may read either neighbour.
  double point_window() const { return reach() + 1e-6; }
};

// Largest |GPU - reference| allowed for a technique's non-ambiguous pixels.
double tolerance(Technique technique, const SamplingPrecision& precision);

}  // namespace penumbra::reference
