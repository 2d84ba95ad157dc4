#include "program_interface.hpp"

#include <algorithm>
#include <string_view>

#include "penumbra/support/param_block.hpp"

namespace penumbra::gl {
namespace {

constexpr std::string_view kBlock = "ShadowParams";

// "a, b, c": the images `role` binds.
std::string image_list(const PassRole& role) {
  std::string names;
  for (std::string_view name : role.images) {
    names += (names.empty() ? "" : ", ") + std::string(name);
  }
  return names;
}

Error interface_error(const PassRole& role, std::string message) {
  return make_error(Error::Kind::bad_input, std::string(role.where), std::move(message));
}

GLint uniform_property(GLuint program, GLuint index, GLenum property) {
  GLint value = 0;
  glGetActiveUniformsiv(program, 1, &index, property, &value);
  return value;
}

Result<std::optional<ParamBlockInfo>> find_block(GLuint program, const PassRole& role) {
  GLint blocks = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORM_BLOCKS, &blocks);
  std::optional<ParamBlockInfo> found;
  for (GLint i = 0; i < blocks; ++i) {
    const GLuint index = static_cast<GLuint>(i);
    GLchar name[256];
    glGetActiveUniformBlockName(program, index, sizeof name, nullptr, name);
    if (name != kBlock) {
      return interface_error(role,
                             "uniform block '" + std::string(name) +
                                 "' is not part of the shader interface; allowed: ShadowParams");
    }
    ParamBlockInfo block;
    glGetActiveUniformBlockiv(program, index, GL_UNIFORM_BLOCK_BINDING, &block.binding);
    glGetActiveUniformBlockiv(program, index, GL_UNIFORM_BLOCK_DATA_SIZE, &block.size);
    found = block;
  }
  return found;
}

// GL names block members "ShadowParams.member" and struct members
// "params.member", which param_block_key turns into their ParamBlock key;
// anything else is not a ShadowParams member.
std::optional<std::string> member_name(std::string_view name, bool in_block) {
  if (in_block) {
    constexpr std::string_view block_prefix = "ShadowParams.";
    if (!name.starts_with(block_prefix)) return std::nullopt;
    return std::string(name.substr(block_prefix.size()));
  }
  if (!name.starts_with("params.")) return std::nullopt;
  return std::string(param_block_key(name));
}

Status add_sampler(ProgramInterface& iface, const PassRole& role, const std::string& name,
                   GLenum type, GLint location) {
  const ImageSlot* slot = find_image_slot(name);
  const bool bound = std::find(role.images.begin(), role.images.end(), name) != role.images.end();
  if (slot == nullptr || !bound) {
    return interface_error(
        role, "sampler '" + name +
                  (slot == nullptr ? "' is not part of the shader interface"
                                   : "' is not bound by the " + std::string(role.where)) +
                  "; allowed names: " + image_list(role));
  }
  if (type != slot->type) {
    return interface_error(role,
                           "sampler '" + name + "' must be a " + std::string(slot->type_name));
  }
  iface.samplers.push_back({name, location});
  return {};
}

}  // namespace

Result<ProgramInterface> reflect_program(GLuint program, const PassRole& role) {
  ProgramInterface iface;
  auto block = find_block(program, role);
  if (!block) return block.error();
  iface.block = *block;
  GLint uniforms = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &uniforms);
  for (GLint i = 0; i < uniforms; ++i) {
    const GLuint index = static_cast<GLuint>(i);
    GLchar buffer[256];
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(program, index, sizeof buffer, nullptr, &size, &type, buffer);
    const std::string name(buffer);
    const bool in_block = uniform_property(program, index, GL_UNIFORM_BLOCK_INDEX) >= 0;
    const GLint location = in_block ? -1 : glGetUniformLocation(program, name.c_str());
    if (type == GL_SAMPLER_2D || type == GL_SAMPLER_2D_SHADOW) {
      PENUMBRA_TRY(add_sampler(iface, role, name, type, location));
      continue;
    }
    const auto member = member_name(name, in_block);
    if (!member) {
      return interface_error(role, "uniform '" + name +
                                       "' is not part of the shader interface; allowed: the "
                                       "members of ShadowParams (block ShadowParams or struct "
                                       "uniform 'params'), " +
                                       image_list(role));
    }
    if (type != GL_FLOAT_VEC4 || size != 1) {
      return interface_error(role, "ShadowParams member '" + *member + "' must be a vec4");
    }
    const GLint offset = in_block ? uniform_property(program, index, GL_UNIFORM_OFFSET) : -1;
    iface.members.push_back({*member, location, offset});
  }
  const std::string_view input = role.images.front();
  const bool has_input = std::any_of(iface.samplers.begin(), iface.samplers.end(),
                                     [&](const auto& s) { return s.name == input; });
  if (!has_input) {
    return interface_error(role, "the fragment stage has no active sampler '" + std::string(input) +
                                     "'; " + std::string(role.input_use));
  }
  return iface;
}

}  // namespace penumbra::gl
