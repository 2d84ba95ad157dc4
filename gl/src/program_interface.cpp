#include "program_interface.hpp"

#include <algorithm>
#include <array>
#include <string_view>

#include "penumbra/support/param_block.hpp"

namespace penumbra::gl {
namespace {

constexpr std::string_view kBlock = "ShadowParams";
constexpr std::string_view kAllowedUniforms =
    "the members of ShadowParams (block ShadowParams or struct uniform 'params'), "
    "shadow_depth, shadow_cmp, receivers";

struct SamplerRole {
  std::string_view name;
  GLenum type;
  std::string_view type_name;
};
constexpr std::array kSamplerRoles = {
    SamplerRole{"shadow_depth", GL_SAMPLER_2D, "sampler2D"},
    SamplerRole{"shadow_cmp", GL_SAMPLER_2D_SHADOW, "sampler2DShadow"},
    SamplerRole{"receivers", GL_SAMPLER_2D, "sampler2D"},
};

Error interface_error(std::string message) {
  return make_error(Error::Kind::bad_input, "query pass", std::move(message));
}

GLint uniform_property(GLuint program, GLuint index, GLenum property) {
  GLint value = 0;
  glGetActiveUniformsiv(program, 1, &index, property, &value);
  return value;
}

Result<std::optional<ParamBlockInfo>> find_block(GLuint program) {
  GLint blocks = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORM_BLOCKS, &blocks);
  std::optional<ParamBlockInfo> found;
  for (GLint i = 0; i < blocks; ++i) {
    const GLuint index = static_cast<GLuint>(i);
    GLchar name[256];
    glGetActiveUniformBlockName(program, index, sizeof name, nullptr, name);
    if (name != kBlock) {
      return interface_error("uniform block '" + std::string(name) +
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

Status add_sampler(ProgramInterface& iface, const std::string& name, GLenum type, GLint location) {
  for (const SamplerRole& role : kSamplerRoles) {
    if (role.name != name) continue;
    if (type != role.type) {
      return interface_error("sampler '" + name + "' must be a " + std::string(role.type_name));
    }
    iface.samplers.push_back({name, location});
    return {};
  }
  return interface_error("sampler '" + name +
                         "' is not part of the shader interface; allowed names: shadow_depth, "
                         "shadow_cmp, receivers");
}

}  // namespace

Result<ProgramInterface> reflect_program(GLuint program) {
  ProgramInterface iface;
  auto block = find_block(program);
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
      PENUMBRA_TRY(add_sampler(iface, name, type, location));
      continue;
    }
    const auto member = member_name(name, in_block);
    if (!member) {
      return interface_error(
          "uniform '" + name +
          "' is not part of the shader interface; allowed: " + std::string(kAllowedUniforms));
    }
    if (type != GL_FLOAT_VEC4 || size != 1) {
      return interface_error("ShadowParams member '" + *member + "' must be a vec4");
    }
    const GLint offset = in_block ? uniform_property(program, index, GL_UNIFORM_OFFSET) : -1;
    iface.members.push_back({*member, location, offset});
  }
  const bool has_receivers = std::any_of(iface.samplers.begin(), iface.samplers.end(),
                                         [](const auto& s) { return s.name == "receivers"; });
  if (!has_receivers) {
    return interface_error(
        "the fragment stage has no active sampler 'receivers'; the query "
        "pass reads each pixel's (u, v, z_r) through it");
  }
  return iface;
}

}  // namespace penumbra::gl
