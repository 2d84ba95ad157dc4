#include "pass_pipeline.hpp"

#include <string>
#include <utility>

#include "vk/shader_module.hpp"

namespace penumbra::detail {
namespace {

Status check_interface(const PassProgram& program, const PassShape& shape) {
  const std::string pass(shape.name);
  auto fail = [&](const std::string& message) {
    return make_error(Error::Kind::bad_input, pass, message);
  };
  if (program.vert.iface.stage != ShaderStage::vertex ||
      program.frag.iface.stage != ShaderStage::fragment) {
    return fail("the program's reflection must describe a vertex stage and a fragment stage");
  }
  const std::string supplied =
      "position (" + std::to_string(shape.position_components) + " floats) at location 0";
  bool has_position = false;
  for (const StageVariable& input : program.vert.iface.inputs) {
    if (input.location != 0) {
      return fail("vertex input '" + input.name + "' at location " +
                  std::to_string(input.location) + " has no data; the " + pass + " supplies only " +
                  supplied);
    }
    if (input.components != shape.position_components) {
      return fail("vertex input '" + input.name + "' has " + std::to_string(input.components) +
                  " components; the " + pass + " supplies " + supplied);
    }
    has_position = true;
  }
  if (!has_position) return fail("the vertex shader has no input at location 0 for " + supplied);
  for (const StageVariable& output : program.frag.iface.outputs) {
    if (output.location == 0) return {};
  }
  return fail("the fragment shader writes no output at location 0, the pass's R32_SFLOAT target");
}

Result<std::vector<vk::DescriptorSetLayout>> create_set_layouts(VkDevice device,
                                                                const BindingPlan& plan) {
  std::vector<vk::DescriptorSetLayout> layouts;
  for (std::uint32_t set = 0; set < plan.set_count; ++set) {
    // Sets the program skips get empty layouts, so set numbers stay as reflected.
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (const PlannedBinding& planned : plan.bindings) {
      if (planned.set != set) continue;
      VkDescriptorSetLayoutBinding binding{};
      binding.binding = planned.binding;
      binding.descriptorType = planned.role == BindingRole::params
                                   ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER
                                   : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
      binding.descriptorCount = 1;
      binding.stageFlags = planned.stages;
      bindings.push_back(binding);
    }
    auto layout = vk::create_descriptor_set_layout(device, bindings, set);
    if (!layout) return layout.error();
    layouts.push_back(std::move(*layout));
  }
  return layouts;
}

}  // namespace

Result<PassPipeline> PassPipeline::create(VkDevice device, const PassProgram& program,
                                          const BindingPlan& plan, const PassShape& shape,
                                          VkRenderPass render_pass) {
  PENUMBRA_TRY(check_interface(program, shape));
  const std::string pass(shape.name);
  auto vertex = vk::create_shader_module(device, program.vert.spirv, pass + " vertex shader");
  if (!vertex) return vertex.error();
  auto fragment = vk::create_shader_module(device, program.frag.spirv, pass + " fragment shader");
  if (!fragment) return fragment.error();

  auto set_layouts = create_set_layouts(device, plan);
  if (!set_layouts) return set_layouts.error();
  std::vector<VkDescriptorSetLayout> handles;
  for (const vk::DescriptorSetLayout& layout : *set_layouts) handles.push_back(layout.get());
  auto layout = vk::create_pipeline_layout(device, handles);
  if (!layout) return layout.error();

  vk::GraphicsPipelineDesc desc;
  desc.vertex = vertex->get();
  desc.vertex_entry = program.vert.iface.entry_point;
  desc.fragment = fragment->get();
  desc.fragment_entry = program.frag.iface.entry_point;
  desc.layout = layout->get();
  desc.render_pass = render_pass;
  desc.position_format = shape.position_format;
  desc.position_stride = shape.position_components * static_cast<std::uint32_t>(sizeof(float));
  desc.depth_test = shape.depth_test;
  auto pipeline = vk::create_graphics_pipeline(device, desc);
  if (!pipeline) return pipeline.error();
  return PassPipeline(std::move(*set_layouts), std::move(*layout), std::move(*pipeline));
}

PassPipeline::PassPipeline(std::vector<vk::DescriptorSetLayout> set_layouts,
                           vk::PipelineLayout layout, vk::GraphicsPipeline pipeline)
    : set_layouts_(std::move(set_layouts)),
      layout_(std::move(layout)),
      pipeline_(std::move(pipeline)) {}

}  // namespace penumbra::detail
