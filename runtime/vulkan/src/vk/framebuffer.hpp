// Framebuffer: the image views a render pass draws into.
#pragma once

#include <vulkan/vulkan.h>

#include <span>

#include "penumbra/support/result.hpp"
#include "vk/device_object.hpp"

namespace penumbra::vk {

using Framebuffer = DeviceObject<VkFramebuffer, vkDestroyFramebuffer>;

// `attachments` in the render pass's attachment order (colour, then depth).
Result<Framebuffer> create_framebuffer(VkDevice device, VkRenderPass render_pass,
                                       std::span<const VkImageView> attachments, VkExtent2D extent);

}  // namespace penumbra::vk
