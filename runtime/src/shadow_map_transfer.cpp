#include "shadow_map_transfer.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "image_transfer.hpp"

namespace penumbra::detail {
namespace {

// Vulkan leaves D32_SFLOAT copies of values outside [0, 1] undefined (without
// VK_EXT_depth_range_unrestricted), so they are refused, not clamped.
Status check_normalized_depth(const FloatImage& image) {
  if (image.channels != 1 || image.data.size() != image.pixel_count()) {
    return make_error(Error::Kind::bad_input, "shadow map",
                      "expected one channel of width * height values; got " +
                          std::to_string(image.channels) + " channels and " +
                          std::to_string(image.data.size()) + " values");
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

}  // namespace

Result<std::unique_ptr<ShadowMapImages>> upload_shadow_map(Context& context,
                                                           const FloatImage& normalized_depth) {
  PENUMBRA_TRY(check_normalized_depth(normalized_depth));
  auto images = create_shadow_map_images(context, normalized_depth.width, normalized_depth.height);
  if (!images) return images.error();
  PENUMBRA_TRY(upload_image(*context.device, *context.commands, (*images)->depth,
                            normalized_depth.data, kMapDepthLayout,
                            "the shadow map's depth image"));
  PENUMBRA_TRY(upload_image(*context.device, *context.commands, (*images)->colour,
                            normalized_depth.data, kMapColourLayout,
                            "the shadow map's colour image"));
  return std::move(*images);
}

Result<FloatImage> read_shadow_map(Context& context, const ShadowMapImages& map) {
  auto texels = read_image(*context.device, *context.commands, map.colour, kMapColourLayout, 1,
                           "the shadow map's colour image");
  if (!texels) return texels.error();
  FloatImage image(static_cast<int>(map.colour.desc().width),
                   static_cast<int>(map.colour.desc().height), 1);
  image.data = std::move(*texels);
  return image;
}

}  // namespace penumbra::detail
