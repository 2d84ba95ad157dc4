#include "vk/framebuffer.hpp"

#include <cstdint>

#include "vk/check.hpp"

namespace penumbra::vk {

Result<Framebuffer> create_framebuffer(VkDevice device, VkRenderPass render_pass,
                                       std::span<const VkImageView> attachments,
                                       VkExtent2D extent) {
  VkFramebufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
  info.renderPass = render_pass;
  info.attachmentCount = static_cast<std::uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.width = extent.width;
  info.height = extent.height;
  info.layers = 1;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkCreateFramebuffer(device, &info, nullptr, &framebuffer),
                     "vkCreateFramebuffer", "creating a framebuffer"));
  return Framebuffer(device, framebuffer);
}

}  // namespace penumbra::vk
