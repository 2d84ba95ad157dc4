#include "shadow_map_transfer.hpp"

#include <utility>

#include "image_transfer.hpp"
#include "penumbra/support/image_checks.hpp"

namespace penumbra::detail {

Result<std::unique_ptr<ShadowMapImages>> upload_shadow_map(Context& context,
                                                           const FloatImage& normalized_depth) {
  PENUMBRA_TRY(check_normalized_depth(normalized_depth));
  auto images =
      create_shadow_map_images(context, normalized_depth.width, normalized_depth.layer_height(),
                               DepthFormat::d32_float, normalized_depth.layers);
  if (!images) return images.error();
  PENUMBRA_TRY(upload_image(*context.device, *context.commands, (*images)->depth,
                            normalized_depth.data, kMapDepthLayout,
                            "the shadow map's depth image"));
  PENUMBRA_TRY(upload_image(*context.device, *context.commands, (*images)->colour,
                            normalized_depth.data, kMapColourLayout,
                            "the shadow map's colour image"));
  return std::move(*images);
}

namespace {

Result<FloatImage> read_map_image(Context& context, const vk::Image& image, VkImageLayout layout,
                                  const std::string& what) {
  auto texels = image.desc().aspect == VK_IMAGE_ASPECT_DEPTH_BIT
                    ? read_depth_image(*context.device, *context.commands, image, layout, what)
                    : read_image(*context.device, *context.commands, image, layout, 1, what);
  if (!texels) return texels.error();
  const auto layers = static_cast<int>(image.desc().layers);
  FloatImage out(static_cast<int>(image.desc().width),
                 static_cast<int>(image.desc().height * image.desc().layer_count()), 1);
  out.layers = layers;
  out.data = std::move(*texels);
  return out;
}

}  // namespace

Result<FloatImage> read_shadow_map(Context& context, const ShadowMapImages& map) {
  return read_map_image(context, map.colour, kMapColourLayout, "the shadow map's colour image");
}

Result<FloatImage> read_shadow_depth(Context& context, const ShadowMapImages& map) {
  return read_map_image(context, map.depth, kMapDepthLayout, "the shadow map's depth image");
}

}  // namespace penumbra::detail
