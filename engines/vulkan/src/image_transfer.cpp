#include "image_transfer.hpp"

#include <cstring>
#include <string>

#include "vk/barrier.hpp"
#include "vk/buffer.hpp"

namespace penumbra::detail {
namespace {

VkBufferImageCopy image_region(const vk::Image& image, std::uint32_t level, VkExtent2D extent) {
  VkBufferImageCopy region{};
  // Zero row length and height: the buffer is tightly packed, row 0 first.
  region.imageSubresource = {image.desc().aspect, level, 0, 1};
  region.imageExtent = {extent.width, extent.height, 1};
  return region;
}

}  // namespace

Status upload_image(const vk::Device& device, vk::CommandContext& commands, const vk::Image& image,
                    std::span<const float> texels, VkImageLayout final_layout,
                    std::string_view what) {
  auto staging = vk::Buffer::create(device, texels.size_bytes(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                    "the staging buffer for " + std::string(what));
  if (!staging) return staging.error();
  std::memcpy(staging->bytes().data(), texels.data(), texels.size_bytes());
  const VkBufferImageCopy region = image_region(image, 0, image.extent());
  return commands.submit(
      [&](VkCommandBuffer cmd) {
        vk::transition(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        vkCmdCopyBufferToImage(cmd, staging->get(), image.get(),
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        vk::transition(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, final_layout);
      },
      "the upload of " + std::string(what));
}

Result<std::vector<float>> read_image(const vk::Device& device, vk::CommandContext& commands,
                                      const vk::Image& image, VkImageLayout layout,
                                      std::uint32_t components, std::string_view what) {
  return read_image_region(device, commands, image, layout, 0, image.extent(), components, what);
}

Result<std::vector<float>> read_image_region(const vk::Device& device, vk::CommandContext& commands,
                                             const vk::Image& image, VkImageLayout layout,
                                             std::uint32_t level, VkExtent2D extent,
                                             std::uint32_t components, std::string_view what) {
  std::vector<float> texels(static_cast<std::size_t>(extent.width) * extent.height * components);
  auto staging =
      vk::Buffer::create(device, texels.size() * sizeof(float), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                         "the readback buffer for " + std::string(what));
  if (!staging) return staging.error();
  const VkBufferImageCopy region = image_region(image, level, extent);
  PENUMBRA_TRY(commands.submit(
      [&](VkCommandBuffer cmd) {
        vk::transition(cmd, image, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        vkCmdCopyImageToBuffer(cmd, image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               staging->get(), 1, &region);
        vk::transition(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout);
        vk::transfer_writes_to_host(cmd);
      },
      "the readback of " + std::string(what)));
  std::memcpy(texels.data(), staging->bytes().data(), texels.size() * sizeof(float));
  return texels;
}

}  // namespace penumbra::detail
