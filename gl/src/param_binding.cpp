#include "param_binding.hpp"

#include <array>
#include <cstring>
#include <string>
#include <vector>

namespace penumbra::gl {
namespace {

std::string given(const ParamBlock& params) {
  std::string names;
  for (const auto& [name, value] : params) names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? "nothing" : names;
}

Result<std::array<float, 4>> value_of(const ParamMember& member, const ParamBlock& params,
                                      const PassRole& role) {
  const auto found = params.find(member.member);
  if (found == params.end()) {
    return make_error(Error::Kind::bad_input, std::string(role.where),
                      "ShadowParams member '" + member.member +
                          "' has no value in the params (given: " + given(params) + ")");
  }
  return found->second;
}

}  // namespace

Result<Buffer> bind_params(GLuint program, const ProgramInterface& iface, const ParamBlock& params,
                           const PassRole& role) {
  if (!iface.block) {
    for (const ParamMember& member : iface.members) {
      auto value = value_of(member, params, role);
      if (!value) return value.error();
      glProgramUniform4fv(program, member.location, 1, value->data());
    }
    return Buffer();
  }
  // Offsets come from the driver, so no std140 arithmetic is assumed here.
  std::vector<std::byte> bytes(static_cast<std::size_t>(iface.block->size));
  for (const ParamMember& member : iface.members) {
    auto value = value_of(member, params, role);
    if (!value) return value.error();
    const std::size_t offset = static_cast<std::size_t>(member.offset);
    if (offset + sizeof(*value) > bytes.size()) {
      return make_error(Error::Kind::internal, std::string(role.where),
                        "ShadowParams member '" + member.member + "' lies outside its block");
    }
    std::memcpy(bytes.data() + offset, value->data(), sizeof(*value));
  }
  Buffer buffer = create_buffer();
  glNamedBufferStorage(buffer.get(), static_cast<GLsizeiptr>(bytes.size()), bytes.data(), 0);
  glBindBufferBase(GL_UNIFORM_BUFFER, static_cast<GLuint>(iface.block->binding), buffer.get());
  return buffer;
}

}  // namespace penumbra::gl
