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

// SamplingPrecision::coordinate_error of an atlas of `width` x `height`
// texels (map_layout atlas): placing uv in it (shaderlib's map_uv()), the
// tile's corner plus the clamped uv times its size, rounds a few float32
// ulps of a coordinate below 1, each at most 2^-24 of the atlas's side;
// 2^-22 of its larger side bounds them with room.
double atlas_coordinate_error(int width, int height);

// Largest |GPU - reference| allowed for a technique's non-ambiguous pixels.
double tolerance(Technique technique, const SamplingPrecision& precision);

}  // namespace penumbra::reference
