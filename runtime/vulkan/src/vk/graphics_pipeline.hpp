// GraphicsPipeline: a vertex + fragment pipeline drawing triangle lists from
// one vertex buffer of float positions into a one-colour-attachment subpass.
// Viewport and scissor are dynamic.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

#include "penumbra/support/result.hpp"
#include "vk/device_object.hpp"

namespace penumbra::vk {

using GraphicsPipeline = DeviceObject<VkPipeline, vkDestroyPipeline>;

struct GraphicsPipelineDesc {
  VkShaderModule vertex = VK_NULL_HANDLE;
  std::string vertex_entry = "main";
  VkShaderModule fragment = VK_NULL_HANDLE;
  std::string fragment_entry = "main";
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  // Vertex attribute at location 0: tightly packed floats of this format.
  VkFormat position_format = VK_FORMAT_UNDEFINED;
  std::uint32_t position_stride = 0;
  // Depth test LESS with writes; needs a render pass with a depth attachment.
  bool depth_test = false;
  bool depth_greater = false;  // with depth_test: GREATER instead (a reversed-Z map)
  // OpenGL's clip volume, z in [-w, w] (VK_EXT_depth_clip_control enabled).
  bool gl_clip_depth = false;
  // Blend ONE, ZERO: the attachment gets what the shader writes, as with
  // blending off, but llvmpipe (lavapipe) then compiles one fragment function
  // instead of two (whole tiles and tile edges). Needs a blendable format.
  bool pass_through_blend = false;
};

Result<GraphicsPipeline> create_graphics_pipeline(VkDevice device,
                                                  const GraphicsPipelineDesc& desc);

}  // namespace penumbra::vk
