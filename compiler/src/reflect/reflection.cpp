#include "penumbra/compiler/reflection.hpp"

#include <algorithm>
#include <spirv_cross/spirv_cross.hpp>

namespace penumbra {
namespace {

using spirv_cross::Compiler;
using spirv_cross::Resource;

UniformBlock reflect_block(const Compiler& compiler, const Resource& resource) {
  UniformBlock block;
  const auto& type = compiler.get_type(resource.base_type_id);
  block.type_name = compiler.get_name(resource.base_type_id);
  block.instance_name = compiler.get_name(resource.id);
  block.set = compiler.get_decoration(resource.id, spv::DecorationDescriptorSet);
  block.binding = compiler.get_decoration(resource.id, spv::DecorationBinding);
  block.size = static_cast<std::uint32_t>(compiler.get_declared_struct_size(type));
  for (std::uint32_t i = 0; i < type.member_types.size(); ++i) {
    block.members.push_back(
        BlockMember{compiler.get_member_name(resource.base_type_id, i),
                    compiler.type_struct_member_offset(type, i),
                    static_cast<std::uint32_t>(compiler.get_declared_struct_member_size(type, i))});
  }
  return block;
}

std::vector<StageVariable> reflect_variables(const Compiler& compiler,
                                             const spirv_cross::SmallVector<Resource>& resources) {
  std::vector<StageVariable> out;
  for (const Resource& resource : resources) {
    const auto& type = compiler.get_type(resource.type_id);
    out.push_back(StageVariable{resource.name,
                                compiler.get_decoration(resource.id, spv::DecorationLocation),
                                type.vecsize});
  }
  std::sort(out.begin(), out.end(),
            [](const StageVariable& a, const StageVariable& b) { return a.location < b.location; });
  return out;
}

}  // namespace

Result<ShaderInterface> reflect(std::span<const std::uint32_t> spirv) {
  try {
    Compiler compiler(std::vector<std::uint32_t>(spirv.begin(), spirv.end()));
    ShaderInterface iface;
    const auto model = compiler.get_execution_model();
    iface.stage = model == spv::ExecutionModelVertex ? ShaderStage::vertex : ShaderStage::fragment;
    const auto entry_points = compiler.get_entry_points_and_stages();
    if (!entry_points.empty()) iface.entry_point = entry_points.front().name;

    const auto resources = compiler.get_shader_resources();
    for (const Resource& resource : resources.uniform_buffers) {
      iface.uniform_blocks.push_back(reflect_block(compiler, resource));
    }
    for (const Resource& resource : resources.sampled_images) {
      const auto& type = compiler.get_type(resource.type_id);
      iface.sampled_images.push_back(SampledImage{
          resource.name, compiler.get_decoration(resource.id, spv::DecorationDescriptorSet),
          compiler.get_decoration(resource.id, spv::DecorationBinding), type.image.depth});
    }
    std::sort(iface.sampled_images.begin(), iface.sampled_images.end(),
              [](const SampledImage& a, const SampledImage& b) { return a.binding < b.binding; });
    iface.inputs = reflect_variables(compiler, resources.stage_inputs);
    iface.outputs = reflect_variables(compiler, resources.stage_outputs);
    return iface;
  } catch (const spirv_cross::CompilerError& error) {
    return make_error(Error::Kind::compile, "reflection", error.what());
  }
}

}  // namespace penumbra
