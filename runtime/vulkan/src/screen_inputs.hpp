// The images full-screen passes read besides the map: the receivers and
// the scene colour, uploaded for sampling.
#pragma once

#include "context.hpp"
#include "penumbra/support/image.hpp"
#include "vk/image.hpp"

namespace penumbra::detail {

// `receivers` checked (channels, size) and uploaded as the RGBA32F receivers
// image, in SHADER_READ_ONLY_OPTIMAL.
Result<vk::Image> upload_receivers(Context& context, const FloatImage& receivers);

// `scene_colour` (four channels) uploaded as an RGBA32F image, in
// SHADER_READ_ONLY_OPTIMAL. Errors (bad_input, "scene colour"): another
// channel count.
Result<vk::Image> upload_scene_colour(Context& context, const FloatImage& scene_colour);

}  // namespace penumbra::detail
