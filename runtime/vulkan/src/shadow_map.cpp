#include "penumbra/vulkan/shadow_map.hpp"

#include <optional>
#include <utility>

#include "formats.hpp"
#include "shadow_map_images.hpp"

namespace penumbra {
namespace detail {

Result<std::unique_ptr<ShadowMapImages>> create_shadow_map_images(const Context& context, int width,
                                                                  int height,
                                                                  DepthFormat depth_format,
                                                                  int layers) {
  PENUMBRA_TRY(context.check_extent(width, height, "shadow map"));
  const VkFormat format = vk_depth_format(depth_format);
  // D32_SFLOAT is checked when the engine starts; D24 is optional in Vulkan.
  if (format != kMapDepthFormat) PENUMBRA_TRY(check_depth_format(*context.device, format));
  const auto w = static_cast<std::uint32_t>(width);
  const auto h = static_cast<std::uint32_t>(height);
  const vk::ImageDesc depth_desc{w,
                                 h,
                                 format,
                                 VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                     VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                     VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                 VK_IMAGE_ASPECT_DEPTH_BIT,
                                 1,
                                 static_cast<std::uint32_t>(layers)};
  auto depth = vk::Image::create(*context.device, depth_desc, "the shadow map's depth image");
  if (!depth) return depth.error();
  const vk::ImageDesc colour_desc{w,
                                  h,
                                  kMapColourFormat,
                                  VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                      VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                      VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                  VK_IMAGE_ASPECT_COLOR_BIT,
                                  1,
                                  static_cast<std::uint32_t>(layers)};
  auto colour = vk::Image::create(*context.device, colour_desc, "the shadow map's colour image");
  if (!colour) return colour.error();
  return std::unique_ptr<ShadowMapImages>(new ShadowMapImages{
      context.device, std::move(*depth), std::move(*colour), std::nullopt, std::nullopt});
}

}  // namespace detail

ShadowMap::ShadowMap(std::unique_ptr<detail::ShadowMapImages> images)
    : images_(std::move(images)) {}

ShadowMap::~ShadowMap() = default;

int ShadowMap::width() const {
  return static_cast<int>(images_->colour.desc().width);
}

int ShadowMap::height() const {
  return static_cast<int>(images_->colour.desc().height);
}

int ShadowMap::minmax_levels() const {
  return images_->minmax ? static_cast<int>(images_->minmax->sizes.size()) : 0;
}

std::optional<double> ShadowMap::depth_gpu_ms() const {
  return images_->depth_gpu_ms;
}

}  // namespace penumbra
