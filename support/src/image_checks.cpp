// Both engines refuse depth outside [0, 1] rather than clamp it: Vulkan leaves
// D32_SFLOAT copies of such values undefined (without
// VK_EXT_depth_range_unrestricted) and GL clamps DEPTH_COMPONENT32F uploads,
// so either would silently run a different map. Receivers are padded to RGBA
// because sampling RGB32F is optional in Vulkan and RGBA32F is not; GL takes
// the same layout so that both engines upload one shape.
#include "penumbra/support/image_checks.hpp"

#include <cmath>
#include <string>

namespace penumbra {

Status check_normalized_depth(const FloatImage& image) {
  if (image.channels != 1 || image.data.size() != image.pixel_count()) {
    return make_error(Error::Kind::bad_input, "shadow map",
                      "expected one channel of width * height values; got " +
                          std::to_string(image.channels) + " channels and " +
                          std::to_string(image.data.size()) + " values");
  }
  if (image.layers < 0 || (image.layers > 0 && image.height % image.layers != 0)) {
    return make_error(Error::Kind::bad_input, "shadow map",
                      "an array of " + std::to_string(image.layers) + " layers cannot stack in " +
                          std::to_string(image.height) + " rows; expected whole layers of " +
                          "equal height");
  }
  for (int j = 0; j < image.height; ++j) {
    for (int i = 0; i < image.width; ++i) {
      const float d = image.at(i, j);
      if (std::isfinite(d) && d >= 0.0f && d <= 1.0f) continue;
      return make_error(Error::Kind::bad_input, "shadow map",
                        "texel (" + std::to_string(i) + ", " + std::to_string(j) + ") is " +
                            std::to_string(d) + "; normalized depth must be in [0, 1]");
    }
  }
  return {};
}

Status check_receivers(const FloatImage& receivers) {
  const bool channels_ok = receivers.channels == 3 || receivers.channels == 4;
  if (channels_ok && receivers.data.size() == receivers.pixel_count() * receivers.channels) {
    return {};
  }
  const std::string got = "; got " + std::to_string(receivers.channels) + " channels and " +
                          std::to_string(receivers.data.size()) + " values for " +
                          std::to_string(receivers.width) + "x" + std::to_string(receivers.height);
  return make_error(
      Error::Kind::bad_input, "receivers",
      "expected 3 or 4 channels (u, v, z_r) and width * height * channels values" + got);
}

std::vector<float> receivers_to_rgba(const FloatImage& receivers) {
  std::vector<float> rgba(receivers.pixel_count() * 4, 0.0f);
  for (std::size_t p = 0; p < receivers.pixel_count(); ++p) {
    for (int c = 0; c < receivers.channels; ++c) {
      rgba[p * 4 + c] = receivers.data[p * receivers.channels + c];
    }
  }
  return rgba;
}

FloatImage channel(const FloatImage& image, int c) {
  FloatImage out(image.width, image.height, 1);
  for (std::size_t p = 0; p < out.data.size(); ++p) {
    out.data[p] = image.data[p * static_cast<std::size_t>(image.channels) + c];
  }
  return out;
}

}  // namespace penumbra
