// RenderPass: one subpass writing a colour attachment and, optionally, a
// depth attachment, both cleared on load and kept on store.
#pragma once

#include <vulkan/vulkan.h>

#include <optional>

#include "penumbra/support/result.hpp"
#include "vk/device_object.hpp"

namespace penumbra::vk {

using RenderPass = DeviceObject<VkRenderPass, vkDestroyRenderPass>;

struct AttachmentDesc {
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkImageLayout final_layout = VK_IMAGE_LAYOUT_UNDEFINED;  // the layout the pass leaves it in
};

struct RenderPassDesc {
  AttachmentDesc colour;
  std::optional<AttachmentDesc> depth;
  // Where the attachments are used next: the pass's writes and final layout
  // transitions are made visible to these stages and accesses.
  VkPipelineStageFlags next_stages = 0;
  VkAccessFlags next_access = 0;
};

Result<RenderPass> create_render_pass(VkDevice device, const RenderPassDesc& desc);

}  // namespace penumbra::vk
