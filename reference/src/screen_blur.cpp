// screen_blur's separable Gaussian blur ("Soft-Edged Shadows";
// docs/techniques.md): one routine for both axes, clamp-to-edge taps, sums in
// double.
#include "penumbra/reference/screen_blur.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace penumbra::reference {
namespace {

// Whether a tap at receiver z `z_tap` is dropped by a depth-aware blur around
// a centre at `z_centre`: the shader's float test
// abs(z_tap - z_centre) > BLUR_DEPTH_TOLERANCE * abs(z_centre). The centre
// itself differs by 0 and is always kept.
bool across_discontinuity(float z_tap, float z_centre) {
  return std::abs(z_tap - z_centre) > kBlurDepthTolerance * std::abs(z_centre);
}

enum class Direction { horizontal, vertical };

FloatImage blur(const FloatImage& factor, std::span<const float> weights,
                const FloatImage* receivers, Direction direction) {
  const int radius = int(weights.size() / 2);
  FloatImage out(factor.width, factor.height, 1);
  for (int y = 0; y < factor.height; ++y) {
    for (int x = 0; x < factor.width; ++x) {
      const float z_centre = receivers ? receivers->at(x, y, 2) : 0.0f;
      double sum = 0.0;
      double kept = 0.0;
      for (int k = -radius; k <= radius; ++k) {
        const int i =
            direction == Direction::horizontal ? std::clamp(x + k, 0, factor.width - 1) : x;
        const int j =
            direction == Direction::vertical ? std::clamp(y + k, 0, factor.height - 1) : y;
        if (receivers && across_discontinuity(receivers->at(i, j, 2), z_centre)) continue;
        const double w = weights[std::size_t(k + radius)];
        sum += w * factor.at(i, j, 0);
        kept += w;
      }
      out.at(x, y) = float(receivers ? sum / kept : sum);
    }
  }
  return out;
}

}  // namespace

FloatImage blur_horizontal(const FloatImage& factor, std::span<const float> weights,
                           const FloatImage* receivers) {
  return blur(factor, weights, receivers, Direction::horizontal);
}

FloatImage blur_vertical(const FloatImage& factor, std::span<const float> weights,
                         const FloatImage* receivers) {
  return blur(factor, weights, receivers, Direction::vertical);
}

FloatImage screen_blur(const Variant& variant, const FloatImage& factor,
                       const FloatImage& receivers) {
  const FloatImage* depth = variant.keys.depth_aware.value_or(false) ? &receivers : nullptr;
  return blur_vertical(blur_horizontal(factor, variant.blur_weights, depth), variant.blur_weights,
                       depth);
}

}  // namespace penumbra::reference
