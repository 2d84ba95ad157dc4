#include "reflected_bindings.hpp"

#include <algorithm>
#include <cstdio>
#include <set>
#include <string_view>

namespace penumbra::gl {
namespace {

// The reflection's names over both stages, each once (a uniform both
// stages declare is one uniform of the program).
struct Declared {
  std::vector<const ConstantBinding*> uniforms;
  std::vector<const BlockBinding*> blocks;
  std::vector<const TextureBinding*> textures;
};

template <typename T>
void add_once(std::vector<const T*>& list, const std::vector<T>& stage) {
  for (const T& entry : stage) {
    if (std::none_of(list.begin(), list.end(), [&](const T* e) { return e->name == entry.name; })) {
      list.push_back(&entry);
    }
  }
}

Declared declared(const PassReflection& reflection) {
  Declared names;
  for (const StageBindings* stage : {&reflection.vert, &reflection.frag}) {
    add_once(names.uniforms, stage->uniforms);
    add_once(names.blocks, stage->blocks);
    add_once(names.textures, stage->textures);
  }
  return names;
}

template <typename T>
const T* find_named(const std::vector<const T*>& list, std::string_view name) {
  for (const T* entry : list) {
    if (entry->name == name) return entry;
  }
  return nullptr;
}

const ConstantBinding* find_member(const BlockBinding& block, std::string_view name) {
  for (const ConstantBinding& member : block.members) {
    if (member.name == name) return &member;
  }
  return nullptr;
}

// Every name the reflection gives the program, for messages.
std::string listed(const Declared& names) {
  std::string list;
  const auto add = [&](const std::string& name) { list += (list.empty() ? "" : ", ") + name; };
  for (const ConstantBinding* uniform : names.uniforms) add(uniform->name);
  for (const BlockBinding* block : names.blocks) {
    add("block " + block->name);
    for (const ConstantBinding& member : block->members) add(member.name);
  }
  for (const TextureBinding* texture : names.textures) add(texture->name);
  return list.empty() ? "nothing" : list;
}

// The GLSL types the reflection gives uniforms and textures, as GL reports them.
struct GlslType {
  std::string_view name;
  GLenum type;
};
constexpr GlslType kTypes[] = {
    {"vec4", GL_FLOAT_VEC4},
    {"sampler2D", GL_SAMPLER_2D},
    {"sampler2DShadow", GL_SAMPLER_2D_SHADOW},
    {"sampler2DArray", GL_SAMPLER_2D_ARRAY},
    {"sampler2DArrayShadow", GL_SAMPLER_2D_ARRAY_SHADOW},
};

std::string type_name(GLenum type) {
  for (const GlslType& known : kTypes) {
    if (known.type == type) return std::string(known.name);
  }
  char code[32];
  std::snprintf(code, sizeof code, "GL type 0x%04X", type);
  return code;
}

Error binding_error(const std::string& where, std::string message) {
  return make_error(Error::Kind::bad_input, where, std::move(message));
}

Status check_type(const std::string& name, GLenum type, const std::string& reflected,
                  const std::string& where) {
  if (type_name(type) == reflected) return {};
  return binding_error(where, "uniform '" + name + "' is a " + type_name(type) +
                                  " in the program; the reflection says " + reflected);
}

GLint uniform_property(GLuint program, GLuint index, GLenum property) {
  GLint value = 0;
  glGetActiveUniformsiv(program, 1, &index, property, &value);
  return value;
}

std::string block_name(GLuint program, GLuint block) {
  GLchar name[256];
  glGetActiveUniformBlockName(program, block, sizeof name, nullptr, name);
  return name;
}

// Everything the program reports active is in the reflection, with its type.
Status check_active(GLuint program, const Declared& names, const std::string& where) {
  GLint blocks = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORM_BLOCKS, &blocks);
  for (GLint b = 0; b < blocks; ++b) {
    const std::string name = block_name(program, static_cast<GLuint>(b));
    if (find_named(names.blocks, name) == nullptr) {
      return binding_error(where, "uniform block '" + name +
                                      "' is active in the program but not in the reflection, "
                                      "which lists: " +
                                      listed(names));
    }
  }
  GLint uniforms = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &uniforms);
  for (GLint i = 0; i < uniforms; ++i) {
    const GLuint index = static_cast<GLuint>(i);
    GLchar buffer[256];
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(program, index, sizeof buffer, nullptr, &size, &type, buffer);
    const std::string name(buffer);
    const GLint block = uniform_property(program, index, GL_UNIFORM_BLOCK_INDEX);
    const std::string* reflected_type = nullptr;
    if (block >= 0) {
      const BlockBinding* reflected = find_named(names.blocks, block_name(program, GLuint(block)));
      const ConstantBinding* member = find_member(*reflected, name);
      if (member != nullptr) reflected_type = &member->type;
    } else if (const ConstantBinding* uniform = find_named(names.uniforms, name)) {
      reflected_type = &uniform->type;
    } else if (const TextureBinding* texture = find_named(names.textures, name)) {
      reflected_type = &texture->type;
    }
    if (reflected_type == nullptr) {
      return binding_error(where, "uniform '" + name +
                                      "' is active in the program but not in the reflection, "
                                      "which lists: " +
                                      listed(names));
    }
    PENUMBRA_TRY(check_type(name, type, *reflected_type, where));
  }
  return {};
}

// The lowest unit or binding point not in `taken`, which it joins.
GLuint lowest_free(std::set<GLuint>& taken) {
  GLuint free = 0;
  while (taken.contains(free)) ++free;
  taken.insert(free);
  return free;
}

Result<std::vector<BlockSlot>> bind_blocks(GLuint program, const Declared& names,
                                           const std::string& where) {
  std::set<GLuint> taken;
  for (const BlockBinding* block : names.blocks) {
    if (block->binding) taken.insert(*block->binding);
  }
  std::vector<BlockSlot> slots;
  for (const BlockBinding* block : names.blocks) {
    const GLuint index = glGetUniformBlockIndex(program, block->name.c_str());
    if (index == GL_INVALID_INDEX) continue;
    GLint size = 0;
    glGetActiveUniformBlockiv(program, index, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
    if (size != GLint(block->size)) {
      return binding_error(where, "uniform block '" + block->name + "' is " + std::to_string(size) +
                                      " bytes in the program; the " + "reflection says " +
                                      std::to_string(block->size));
    }
    BlockSlot slot{block, 0, {}};
    if (block->binding) {
      GLint binding = 0;
      glGetActiveUniformBlockiv(program, index, GL_UNIFORM_BLOCK_BINDING, &binding);
      if (binding != GLint(*block->binding)) {
        return binding_error(
            where, "uniform block '" + block->name + "' has binding " + std::to_string(binding) +
                       " in the program; the reflection says " + std::to_string(*block->binding));
      }
      slot.binding = *block->binding;
    } else {
      slot.binding = lowest_free(taken);
      glUniformBlockBinding(program, index, slot.binding);
    }
    for (const ConstantBinding& member : block->members) {
      const GLchar* name = member.name.c_str();
      GLuint member_index = GL_INVALID_INDEX;
      glGetUniformIndices(program, 1, &name, &member_index);
      if (member_index == GL_INVALID_INDEX) continue;
      const GLint offset = uniform_property(program, member_index, GL_UNIFORM_OFFSET);
      if (!member.offset || offset != GLint(*member.offset) ||
          *member.offset + member.size > block->size) {
        return binding_error(
            where, "uniform '" + member.name + "' is at offset " + std::to_string(offset) +
                       " of its block in the program; " + "the reflection says " +
                       (member.offset ? std::to_string(*member.offset) : std::string("nothing")) +
                       " (" + std::to_string(member.size) + " bytes of " +
                       std::to_string(block->size) + ")");
      }
      slot.members.push_back(&member);
    }
    slots.push_back(std::move(slot));
  }
  return slots;
}

Result<std::vector<TextureSlot>> bind_textures(GLuint program, const Declared& names,
                                               const std::string& where) {
  GLint unit_count = 0;
  glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &unit_count);
  std::vector<TextureSlot> slots;
  std::set<GLuint> taken;
  // Declared units first, so that the assigned ones avoid them.
  for (const bool declared_unit : {true, false}) {
    for (const TextureBinding* binding : names.textures) {
      if (binding->binding.has_value() != declared_unit) continue;
      const GLint location = glGetUniformLocation(program, binding->name.c_str());
      if (location < 0) continue;
      const TextureDescription* texture = find_bound_texture(binding->name);
      if (texture == nullptr) {
        return binding_error(where, "the reflection's texture '" + binding->name +
                                        "' is not a texture of the shader contract");
      }
      GLuint unit = 0;
      if (declared_unit) {
        unit = *binding->binding;
        GLint declared = -1;
        glGetUniformiv(program, location, &declared);
        if (declared != GLint(unit)) {
          return binding_error(
              where, "texture '" + binding->name + "' has binding " + std::to_string(declared) +
                         " in the program; the reflection says " + std::to_string(unit));
        }
        for (const TextureSlot& other : slots) {
          if (other.unit == unit) {
            return binding_error(where, "textures '" + other.binding->name + "' and '" +
                                            binding->name + "' both have binding " +
                                            std::to_string(unit) + " in the reflection");
          }
        }
        taken.insert(unit);
      } else {
        unit = lowest_free(taken);
        glProgramUniform1i(program, location, GLint(unit));
      }
      if (unit >= GLuint(unit_count)) {
        return binding_error(where, "texture '" + binding->name + "' needs texture unit " +
                                        std::to_string(unit) + "; GL has units 0 to " +
                                        std::to_string(unit_count - 1));
      }
      slots.push_back({binding, texture->id, unit});
    }
  }
  return slots;
}

}  // namespace

Result<PassBindings> bind_by_reflection(GLuint program, const PassReflection& reflection,
                                        const std::string& where) {
  const Declared names = declared(reflection);
  PENUMBRA_TRY(check_active(program, names, where));
  PassBindings bindings;
  for (const ConstantBinding* uniform : names.uniforms) {
    const GLint location = glGetUniformLocation(program, uniform->name.c_str());
    if (location >= 0) bindings.uniforms.push_back({uniform, location});
  }
  auto blocks = bind_blocks(program, names, where);
  if (!blocks) return blocks.error();
  bindings.blocks = std::move(*blocks);
  auto textures = bind_textures(program, names, where);
  if (!textures) return textures.error();
  bindings.textures = std::move(*textures);
  return bindings;
}

}  // namespace penumbra::gl
