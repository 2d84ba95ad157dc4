#include <string>

#include "reflect_parts.hpp"

namespace penumbra::detail {
namespace {

using spirv_cross::Compiler;
using spirv_cross::SPIRType;

// Struct members become "<member>.<field>" at offset base + their own; an
// array of structs stays one member, as GLSL and HLSL cannot set it whole.
void flatten(const Compiler& compiler, const SPIRType& type, std::uint32_t base,
             const std::string& prefix, std::vector<BlockMember>& out) {
  for (std::uint32_t i = 0; i < type.member_types.size(); ++i) {
    const std::string name = prefix + compiler.get_member_name(type.self, i);
    const std::uint32_t offset = base + compiler.type_struct_member_offset(type, i);
    const SPIRType& member = compiler.get_type(type.member_types[i]);
    if (member.basetype == SPIRType::Struct && member.array.empty()) {
      flatten(compiler, member, offset, name + ".", out);
    } else {
      const auto size = compiler.get_declared_struct_member_size(type, i);
      out.push_back(BlockMember{name, offset, static_cast<std::uint32_t>(size)});
    }
  }
}

}  // namespace

UniformBlock reflect_block(const Compiler& compiler, const spirv_cross::Resource& resource) {
  UniformBlock block;
  const SPIRType& type = compiler.get_type(resource.base_type_id);
  block.type_name = compiler.get_name(resource.base_type_id);
  block.instance_name = compiler.get_name(resource.id);
  block.set = compiler.get_decoration(resource.id, spv::DecorationDescriptorSet);
  block.binding = compiler.get_decoration(resource.id, spv::DecorationBinding);
  block.size = static_cast<std::uint32_t>(compiler.get_declared_struct_size(type));
  flatten(compiler, type, 0, "", block.members);
  return block;
}

}  // namespace penumbra::detail
