#include "image_transfer.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "formats.hpp"
#include "penumbra/model/depth_format.hpp"
#include "vk/barrier.hpp"
#include "vk/buffer.hpp"

namespace penumbra::detail {
namespace {

VkBufferImageCopy image_region(const vk::Image& image, std::uint32_t level, VkExtent2D extent) {
  VkBufferImageCopy region{};
  // Zero row length and height: the buffer is tightly packed, row 0 first,
  // layer after layer.
  region.imageSubresource = {image.desc().aspect, level, 0, image.desc().layer_count()};
  region.imageExtent = {extent.width, extent.height, 1};
  return region;
}

// `bytes_per_texel` bytes of each texel in [0, extent) of level `level`,
// tightly packed, row 0 first, layer after layer.
Result<std::vector<std::byte>> read_bytes(const vk::Device& device, vk::CommandContext& commands,
                                          const vk::Image& image, VkImageLayout layout,
                                          std::uint32_t level, VkExtent2D extent,
                                          std::size_t bytes_per_texel, std::string_view what) {
  std::vector<std::byte> bytes(std::size_t{extent.width} * extent.height *
                               image.desc().layer_count() * bytes_per_texel);
  auto staging = vk::Buffer::create(device, bytes.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
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
  std::memcpy(bytes.data(), staging->bytes().data(), bytes.size());
  return bytes;
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
  PENUMBRA_TRY_ASSIGN(
      const std::vector<std::byte> bytes,
      read_bytes(device, commands, image, layout, level, extent, components * sizeof(float), what));
  std::vector<float> texels(bytes.size() / sizeof(float));
  std::memcpy(texels.data(), bytes.data(), bytes.size());
  return texels;
}

Result<std::vector<float>> read_depth_image(const vk::Device& device, vk::CommandContext& commands,
                                            const vk::Image& image, VkImageLayout layout,
                                            std::string_view what) {
  const DepthFormat depth = depth_format_of(image.desc().format).value_or(DepthFormat::d32_float);
  if (depth == DepthFormat::d32_float) return read_image(device, commands, image, layout, 1, what);
  // Copies of D16 give 16-bit codes; of X8_D24, 32-bit words whose low 24
  // bits are the code.
  const bool d16 = depth == DepthFormat::d16_unorm;
  const std::size_t size = d16 ? sizeof(std::uint16_t) : sizeof(std::uint32_t);
  PENUMBRA_TRY_ASSIGN(const std::vector<std::byte> bytes,
                      read_bytes(device, commands, image, layout, 0, image.extent(), size, what));
  std::vector<float> texels;
  texels.reserve(bytes.size() / size);
  for (std::size_t at = 0; at < bytes.size(); at += size) {
    std::uint32_t code = 0;
    if (d16) {
      std::uint16_t code16 = 0;
      std::memcpy(&code16, bytes.data() + at, size);
      code = code16;
    } else {
      std::memcpy(&code, bytes.data() + at, size);
      code &= 0xFFFFFFu;
    }
    texels.push_back(unorm_depth(depth, code));
  }
  return texels;
}

}  // namespace penumbra::detail
