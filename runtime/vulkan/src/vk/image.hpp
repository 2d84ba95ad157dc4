// Image: a 2D VkImage (or 2D array) in device-local memory with one or more
// mip levels, and a view of all of them. Layouts are managed by whoever
// records commands on it, for all levels and layers at once.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string_view>

#include "penumbra/support/result.hpp"
#include "vk/device.hpp"
#include "vk/device_object.hpp"
#include "vk/memory.hpp"

namespace penumbra::vk {

struct ImageDesc {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkImageUsageFlags usage = 0;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;  // of the view and of transfers
  std::uint32_t mip_levels = 1;  // level m is max(1, width >> m) x max(1, height >> m)
  std::uint32_t layers = 0;      // 0: a 2D image and view; n: n layers, an array view

  // The image's array layers: 1 for a 2D image.
  std::uint32_t layer_count() const { return layers > 0 ? layers : 1; }
};

class Image {
 public:
  // `what` names the image in error messages ("the shadow depth image").
  static Result<Image> create(const Device& device, const ImageDesc& desc, std::string_view what);

  VkImage get() const { return image_.get(); }
  VkImageView view() const { return view_.get(); }
  const ImageDesc& desc() const { return desc_; }
  VkExtent2D extent() const { return {desc_.width, desc_.height}; }

 private:
  Image(const ImageDesc& desc, DeviceMemory memory, DeviceObject<VkImage, vkDestroyImage> image,
        DeviceObject<VkImageView, vkDestroyImageView> view);

  ImageDesc desc_;
  // Destroyed in reverse order: the view, then the image, then its memory.
  DeviceMemory memory_;
  DeviceObject<VkImage, vkDestroyImage> image_;
  DeviceObject<VkImageView, vkDestroyImageView> view_;
};

}  // namespace penumbra::vk
