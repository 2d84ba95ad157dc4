#include "param_binding.hpp"

#include <algorithm>
#include <array>
#include <cstring>

namespace penumbra::gl {
namespace {

std::string given(const ParamBlock& params) {
  std::string names;
  for (const auto& [name, value] : params) names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? "nothing" : names;
}

Result<std::array<float, 4>> value_of(const ConstantBinding& constant, const ParamBlock& params,
                                      const std::string& where) {
  const auto found = params.find(constant.parameter);
  if (found == params.end()) {
    return make_error(Error::Kind::bad_input, where,
                      "ShadowParams member '" + constant.parameter + "' (uniform '" +
                          constant.name + "') has no value in the params (given: " + given(params) +
                          ")");
  }
  return found->second;
}

}  // namespace

Result<std::vector<Buffer>> bind_params(GLuint program, const PassBindings& bindings,
                                        const ParamBlock& params, const std::string& where) {
  // bind_by_reflection admitted only vec4 constants.
  for (const UniformSlot& uniform : bindings.uniforms) {
    auto value = value_of(*uniform.constant, params, where);
    if (!value) return value.error();
    glProgramUniform4fv(program, uniform.location, 1, value->data());
  }
  std::vector<Buffer> buffers;
  for (const BlockSlot& slot : bindings.blocks) {
    std::vector<std::byte> bytes(slot.block->size);
    for (const ConstantBinding* member : slot.members) {
      auto value = value_of(*member, params, where);
      if (!value) return value.error();
      // bind_by_reflection checked that the member lies inside the block.
      std::memcpy(bytes.data() + *member->offset, value->data(),
                  std::min<std::size_t>(member->size, sizeof(*value)));
    }
    Buffer buffer = create_buffer();
    glNamedBufferStorage(buffer.get(), static_cast<GLsizeiptr>(bytes.size()), bytes.data(), 0);
    glBindBufferBase(GL_UNIFORM_BUFFER, slot.binding, buffer.get());
    buffers.push_back(std::move(buffer));
  }
  return buffers;
}

}  // namespace penumbra::gl
