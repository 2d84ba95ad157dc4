#include "vk/barrier.hpp"

namespace penumbra::vk {
namespace {

struct LayoutUse {
  VkPipelineStageFlags stages;
  VkAccessFlags access;
};

// The stages and accesses that use an image in `layout`, in this runtime.
LayoutUse use_of(VkImageLayout layout) {
  switch (layout) {
    case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL:
      return {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT};
    case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL:
      return {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT};
    case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL:
    case VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL:
      return {VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT};
    case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL:
      return {VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT};
    default:  // VK_IMAGE_LAYOUT_UNDEFINED: nothing to wait for
      return {VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0};
  }
}

// One barrier on all of `image`'s mip levels.
void image_barrier(VkCommandBuffer commands, const Image& image, VkImageLayout from,
                   VkImageLayout to, LayoutUse before, LayoutUse after) {
  VkImageMemoryBarrier barrier{};
  barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
  barrier.srcAccessMask = before.access;
  barrier.dstAccessMask = after.access;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image.get();
  barrier.subresourceRange = {image.desc().aspect, 0, image.desc().mip_levels, 0,
                              image.desc().layer_count()};
  vkCmdPipelineBarrier(commands, before.stages, after.stages, 0, 0, nullptr, 0, nullptr, 1,
                       &barrier);
}

}  // namespace

void transition(VkCommandBuffer commands, const Image& image, VkImageLayout from,
                VkImageLayout to) {
  if (from == to) return;
  image_barrier(commands, image, from, to, use_of(from), use_of(to));
}

void between_transfer_writes(VkCommandBuffer commands, const Image& image) {
  const LayoutUse write = use_of(VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  image_barrier(commands, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, write, write);
}

void transfer_writes_to_host(VkCommandBuffer commands) {
  VkMemoryBarrier barrier{};
  barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &barrier, 0, nullptr, 0, nullptr);
}

}  // namespace penumbra::vk
