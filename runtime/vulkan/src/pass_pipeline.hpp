// PassPipeline: the pipeline of one pass program, with the descriptor set
// layouts and pipeline layout built from its reflection.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string_view>
#include <vector>

#include "formats.hpp"
#include "penumbra/vulkan/program.hpp"
#include "reflection_binding.hpp"
#include "vk/descriptor_set_layout.hpp"
#include "vk/graphics_pipeline.hpp"
#include "vk/pipeline_layout.hpp"

namespace penumbra::detail {

// What a pass feeds its program and how it draws.
struct PassShape {
  std::string_view name;                           // "depth pass", "query pass": names errors
  ColourTarget target;                             // what output 0 is drawn into
  VkFormat position_format = VK_FORMAT_UNDEFINED;  // the vertex data at location 0
  std::uint32_t position_components = 0;           // floats per vertex
  bool depth_test = false;
  bool fragment_depth = false;  // the fragment shader must write the fragment depth
  // With depth_test: GREATER, depth and colour cleared to 0 (a reversed-Z map).
  bool depth_greater = false;
};

class PassPipeline {
 public:
  // Checks the program's stages against `shape`: vertex input (location 0
  // only, of the shape's width), a clip-space position, fragment output
  // (location 0 only, with at least the target's components) and, where the
  // shape asks, the fragment depth. Then
  // builds one descriptor set layout per set of `plan`.
  // `software`: the device is a CPU rasterizer (lavapipe), whose passes
  // without a depth test blend ONE, ZERO to compile once (see
  // vk::GraphicsPipelineDesc::pass_through_blend).
  static Result<PassPipeline> create(VkDevice device, const PassProgram& program,
                                     const BindingPlan& plan, const PassShape& shape,
                                     VkRenderPass render_pass, bool software);

  VkPipeline get() const { return pipeline_.get(); }
  VkPipelineLayout layout() const { return layout_.get(); }
  VkDescriptorSetLayout set_layout(std::uint32_t set) const { return set_layouts_[set].get(); }

 private:
  PassPipeline(std::vector<vk::DescriptorSetLayout> set_layouts, vk::PipelineLayout layout,
               vk::GraphicsPipeline pipeline);

  std::vector<vk::DescriptorSetLayout> set_layouts_;
  vk::PipelineLayout layout_;
  vk::GraphicsPipeline pipeline_;
};

}  // namespace penumbra::detail
