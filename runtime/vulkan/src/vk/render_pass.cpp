#include "vk/render_pass.hpp"

#include <cstdint>
#include <vector>

#include "vk/check.hpp"

namespace penumbra::vk {
namespace {

VkAttachmentDescription cleared_attachment(const AttachmentDesc& desc) {
  VkAttachmentDescription attachment{};
  attachment.format = desc.format;
  attachment.samples = VK_SAMPLE_COUNT_1_BIT;
  attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  // Every pass overwrites its attachments completely, so old contents never matter.
  attachment.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  attachment.finalLayout = desc.final_layout;
  return attachment;
}

}  // namespace

Result<RenderPass> create_render_pass(VkDevice device, const RenderPassDesc& desc) {
  std::vector<VkAttachmentDescription> attachments{cleared_attachment(desc.colour)};
  const VkAttachmentReference colour_ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  const VkAttachmentReference depth_ref{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};

  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colour_ref;

  VkSubpassDependency done{};
  done.srcSubpass = 0;
  done.dstSubpass = VK_SUBPASS_EXTERNAL;
  done.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  done.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  done.dstStageMask = desc.next_stages;
  done.dstAccessMask = desc.next_access;

  if (desc.depth) {
    attachments.push_back(cleared_attachment(*desc.depth));
    subpass.pDepthStencilAttachment = &depth_ref;
    done.srcStageMask |= VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    done.srcAccessMask |= VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  }

  VkRenderPassCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  info.attachmentCount = static_cast<std::uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &done;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  PENUMBRA_TRY(check(vkCreateRenderPass(device, &info, nullptr, &render_pass), "vkCreateRenderPass",
                     "creating a render pass"));
  return RenderPass(device, render_pass);
}

}  // namespace penumbra::vk
