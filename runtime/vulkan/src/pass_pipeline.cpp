#include "pass_pipeline.hpp"

#include <algorithm>
#include <string>
#include <string_view>
#include <utility>

#include "vk/shader_module.hpp"

namespace penumbra::detail {
namespace {

Error fail(const std::string& pass, std::string message) {
  return make_error(Error::Kind::bad_input, pass, std::move(message));
}

bool declares_builtin(const ShaderInterface& iface, std::string_view builtin) {
  return std::find(iface.builtin_outputs.begin(), iface.builtin_outputs.end(), builtin) !=
         iface.builtin_outputs.end();
}

// Direct3D 9's input registers are float4, and vkd3d declares the
// translated input so: the input assembler fills what the vertex data lacks
// with (0, 0, 1), as Direct3D's does.
bool reads_position(const PassProgram& program, const StageVariable& input,
                    const PassShape& shape) {
  return input.components == shape.position_components ||
         (program.d3d_bytecode && input.components == 4);
}

Status check_vertex_stage(const PassProgram& program, const PassShape& shape) {
  const ShaderInterface& vert = program.vert.iface;
  const std::string pass(shape.name);
  const std::string supplied =
      "position (" + std::to_string(shape.position_components) + " floats) at location 0";
  bool has_position = false;
  for (const StageVariable& input : vert.inputs) {
    if (input.location != 0) {
      return fail(pass, "vertex input '" + input.name + "' at location " +
                            std::to_string(input.location) + " has no data; the " + pass +
                            " supplies only " + supplied);
    }
    if (!reads_position(program, input, shape)) {
      return fail(pass, "vertex input '" + input.name + "' has " +
                            std::to_string(input.components) + " components; the " + pass +
                            " supplies " + supplied);
    }
    has_position = true;
  }
  if (!has_position) {
    return fail(pass, "the vertex shader has no input at location 0 for " + supplied);
  }
  // glslang's HLSL front end makes Direct3D 9's POSITION semantic a plain
  // output: the rasterizer would get no position at all.
  if (!declares_builtin(vert, "Position")) {
    return fail(pass,
                "the vertex shader writes no clip-space position (BuiltIn Position: GLSL "
                "gl_Position, HLSL SV_Position)");
  }
  return {};
}

// Outputs without an attachment would be dropped silently; among them
// Direct3D 9's DEPTH semantic, which glslang makes a plain output.
Status check_fragment_stage(const ShaderInterface& frag, const PassShape& shape) {
  const std::string pass(shape.name);
  const std::string target(shape.target.format);
  bool has_output = false;
  for (const StageVariable& output : frag.outputs) {
    if (output.location != 0) {
      return fail(pass, "fragment output '" + output.name + "' at location " +
                            std::to_string(output.location) + " has no attachment; the " + pass +
                            " has one " + target + " target, at location 0");
    }
    if (output.components < shape.target.components) {
      return fail(pass, "fragment output '" + output.name + "' has " +
                            std::to_string(output.components) + " component(s); the " + pass +
                            "'s " + target + " target takes " +
                            std::to_string(shape.target.components));
    }
    has_output = true;
  }
  if (!has_output) {
    return fail(pass, "the fragment shader writes no output at location 0, the pass's " + target +
                          " target");
  }
  if (shape.fragment_depth && !declares_builtin(frag, "FragDepth")) {
    return fail(pass,
                "the fragment shader writes no fragment depth (BuiltIn FragDepth: GLSL "
                "gl_FragDepth, HLSL SV_Depth); the " +
                    pass +
                    " stores the same normalized depth in the map's depth image as in output 0");
  }
  return {};
}

Status check_interface(const PassProgram& program, const PassShape& shape) {
  if (program.vert.iface.stage != ShaderStage::vertex ||
      program.frag.iface.stage != ShaderStage::fragment) {
    return fail(std::string(shape.name),
                "the program's reflection must describe a vertex stage and a fragment stage");
  }
  PENUMBRA_TRY(check_vertex_stage(program, shape));
  return check_fragment_stage(program.frag.iface, shape);
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
      binding.descriptorType = planned.type;
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
                                          VkRenderPass render_pass, bool software) {
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
  desc.depth_greater = shape.depth_greater;
  desc.gl_clip_depth = program.gl_clip_depth;
  // A depth-tested pass already compiles once; every colour target is float.
  desc.pass_through_blend = software && !shape.depth_test;
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
