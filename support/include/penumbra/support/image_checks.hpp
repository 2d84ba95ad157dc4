// The checks the engines make on a query pass's input images, the
// receivers' RGBA layout they upload, and one channel of what they read back.
#pragma once

#include <vector>

#include "penumbra/support/image.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

// Errors (bad_input, "shadow map"): not one channel of width * height values,
// layers that do not stack in its height, or a texel that is not finite
// depth in [0, 1].
Status check_normalized_depth(const FloatImage& image);

// Errors (bad_input, "receivers"): not 3 or 4 channels (u, v, z_r) of
// width * height * channels values.
Status check_receivers(const FloatImage& receivers);

// The receivers as 4 channels per pixel, a missing fourth channel 0.
std::vector<float> receivers_to_rgba(const FloatImage& receivers);

// Channel `c` of `image`, as a one-channel image.
FloatImage channel(const FloatImage& image, int c);

}  // namespace penumbra
