// Pipeline barriers for the runtime's few image layouts and for readbacks.
#pragma once

#include <vulkan/vulkan.h>

#include "vk/image.hpp"

namespace penumbra::vk {

// Moves `image` (all its mip levels) from layout `from` to `to`, ordering the
// accesses each layout implies (transfer, fragment shader read, attachment
// write). No-op when equal.
void transition(VkCommandBuffer commands, const Image& image, VkImageLayout from, VkImageLayout to);

// Orders one transfer write to `image` (in TRANSFER_DST_OPTIMAL) before the next.
void between_transfer_writes(VkCommandBuffer commands, const Image& image);

// Makes transfer writes (image-to-buffer copies) visible to the host.
void transfer_writes_to_host(VkCommandBuffer commands);

}  // namespace penumbra::vk
