#include "vk/image.hpp"

#include <string>
#include <utility>

#include "vk/check.hpp"

namespace penumbra::vk {

Result<Image> Image::create(const Device& device, const ImageDesc& desc, std::string_view what) {
  const std::string levels =
      desc.mip_levels > 1 ? ", " + std::to_string(desc.mip_levels) + " mip levels" : "";
  const std::string layers =
      desc.layers > 0 ? ", " + std::to_string(desc.layers) + " array layers" : "";
  const std::string name = std::string(what) + " (" + std::to_string(desc.width) + "x" +
                           std::to_string(desc.height) + " " + format_name(desc.format) + levels +
                           layers + ")";
  VkImageCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = desc.format;
  info.extent = {desc.width, desc.height, 1};
  info.mipLevels = desc.mip_levels;
  info.arrayLayers = desc.layer_count();
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage raw_image = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkCreateImage(device.get(), &info, nullptr, &raw_image), "vkCreateImage",
                     "creating " + name));
  DeviceObject<VkImage, vkDestroyImage> image(device.get(), raw_image);

  VkMemoryRequirements requirements{};
  vkGetImageMemoryRequirements(device.get(), raw_image, &requirements);
  auto memory = allocate_memory(device, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, name);
  if (!memory) return memory.error();
  PENUMBRA_TRY(check(vkBindImageMemory(device.get(), raw_image, memory->get(), 0),
                     "vkBindImageMemory", "binding memory to " + name));

  VkImageViewCreateInfo view_info{};
  view_info.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
  view_info.image = raw_image;
  view_info.viewType = desc.layers > 0 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
  view_info.format = desc.format;
  view_info.subresourceRange = {desc.aspect, 0, desc.mip_levels, 0, desc.layer_count()};
  VkImageView raw_view = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkCreateImageView(device.get(), &view_info, nullptr, &raw_view),
                     "vkCreateImageView", "creating a view of " + name));
  return Image(desc, std::move(*memory), std::move(image),
               DeviceObject<VkImageView, vkDestroyImageView>(device.get(), raw_view));
}

Image::Image(const ImageDesc& desc, DeviceMemory memory,
             DeviceObject<VkImage, vkDestroyImage> image,
             DeviceObject<VkImageView, vkDestroyImageView> view)
    : desc_(desc), memory_(std::move(memory)), image_(std::move(image)), view_(std::move(view)) {}

}  // namespace penumbra::vk
