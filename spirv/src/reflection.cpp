#include "penumbra/spirv/reflection.hpp"

#include <algorithm>
#include <spirv_cross/spirv_cross.hpp>

#include "reflect_parts.hpp"

namespace penumbra {
namespace {

using spirv_cross::Compiler;
using spirv_cross::Resource;

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

// The outputs a vertex or fragment stage can declare, by their SPIR-V names.
std::string builtin_name(spv::BuiltIn builtin) {
  switch (builtin) {
    case spv::BuiltInPosition:
      return "Position";
    case spv::BuiltInPointSize:
      return "PointSize";
    case spv::BuiltInClipDistance:
      return "ClipDistance";
    case spv::BuiltInCullDistance:
      return "CullDistance";
    case spv::BuiltInFragDepth:
      return "FragDepth";
    case spv::BuiltInSampleMask:
      return "SampleMask";
    default:
      return "BuiltIn" + std::to_string(static_cast<int>(builtin));
  }
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
      iface.uniform_blocks.push_back(detail::reflect_block(compiler, resource));
    }
    iface.inputs = reflect_variables(compiler, resources.stage_inputs);
    iface.outputs = reflect_variables(compiler, resources.stage_outputs);
    for (const spirv_cross::BuiltInResource& builtin : resources.builtin_outputs) {
      iface.builtin_outputs.push_back(builtin_name(builtin.builtin));
    }
    detail::reflect_images(compiler, resources, spirv, iface);
    return iface;
  } catch (const spirv_cross::CompilerError& error) {
    return make_error(Error::Kind::compile, "reflection", error.what());
  }
}

}  // namespace penumbra
