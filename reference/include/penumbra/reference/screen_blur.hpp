// screen_blur's chain after the factor pass ("Soft-Edged Shadows", docs/verification.md
// "screen_blur"): a separable Gaussian blur of the screen-space shadow factor
// and a composite onto a scene colour. The factor itself is what evaluate()
// and evaluate_image() return for screen_blur. Images are screen-sized and
// row-major; a pixel (x, y) of the blur reads pixel (clamp(x + k), y) of its
// input (clamp-to-edge: a tap past the edge reads the edge pixel).
#pragma once

#include <span>

#include "penumbra/model/model.hpp"
#include "penumbra/support/image.hpp"

namespace penumbra::reference {

// Largest |GPU - CPU| allowed for the blurred factor when the CPU blurs the
// GPU's own factor image: float32 sums of at most 65 taps in [0, 1] against
// double ones.
inline constexpr double kBlurTolerance = 1e-5;
// Largest |GPU - CPU| allowed per channel for the composite against the
// scene colour times the GPU's blurred factor: one float product each.
inline constexpr double kCompositeTolerance = 1e-6;

// One blur pass over channel 0 of `factor`, into a 1-channel image of its
// size: out(x, y) = sum_k w_k factor(clamp(x + k), y) for k = -R..R, with
// `weights` the 2R + 1 taps -R..R (an odd count). With `receivers` (3 or 4
// channels, u, v, z_r, the factor's size) the pass is depth-aware: a tap whose
// receiver z differs from the centre's by more than kBlurDepthTolerance times
// |z_centre| (tested in float, as the shader does) gets weight 0 and the
// sum is divided by the kept weights (the centre is always kept). Sums are
// accumulated in double.
FloatImage blur_horizontal(const FloatImage& factor, std::span<const float> weights,
                           const FloatImage* receivers);
// The same along columns: out(x, y) = sum_k w_k factor(x, clamp(y + k)).
FloatImage blur_vertical(const FloatImage& factor, std::span<const float> weights,
                         const FloatImage* receivers);

// Both passes with `variant`'s blur_weights, depth-aware when its depth_aware
// key is true: blur_vertical(blur_horizontal(factor)). `variant` must pass
// check_variant(); `receivers` (3 or 4 channels) must have the factor's size.
FloatImage screen_blur(const Variant& variant, const FloatImage& factor,
                       const FloatImage& receivers);

// The composite pass: (r, g, b) * blurred, alpha kept, per pixel, in float as
// the shader computes it. `colour` has 4 channels; channel 0 of `blurred` is
// read; both have one size. Returns a 4-channel image.
FloatImage composite(const FloatImage& colour, const FloatImage& blurred);

// The procedural scene colour of screen_blur's verification, 4 channels:
// a checkerboard of kSceneColourCell-pixel squares, square (0, 0) in
// (1, 0.5, 0.25) and its neighbours in (0.25, 0.75, 1), alpha 1 everywhere.
// Every channel differs between the two colours, and all values are exact
// in float.
inline constexpr int kSceneColourCell = 16;
FloatImage scene_colour(int width, int height);

}  // namespace penumbra::reference
