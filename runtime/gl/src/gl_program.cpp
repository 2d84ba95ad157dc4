#include "gl_program.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "texel_formats.hpp"

namespace penumbra::gl {
namespace {

// The engine's geometry: positions of GL_FLOAT components.
constexpr std::string_view kPositionFormat = "GL_FLOAT";

// The driver's log without trailing newlines (Mesa ends each line with one).
std::string trimmed(std::string log) {
  while (!log.empty() && (log.back() == '\n' || log.back() == '\0' || log.back() == ' ')) {
    log.pop_back();
  }
  return log.empty() ? "(the driver gave no log)" : log;
}

std::string shader_log(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  return trimmed(std::move(log));
}

std::string program_log(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  glGetProgramInfoLog(program, length, nullptr, log.data());
  return trimmed(std::move(log));
}

Result<Shader> compile(GLenum stage, std::string_view text, const char* stage_name,
                       const std::string& where) {
  Shader shader(glCreateShader(stage));
  const GLchar* source = text.data();
  const GLint length = static_cast<GLint>(text.size());
  glShaderSource(shader.get(), 1, &source, &length);
  glCompileShader(shader.get());
  GLint compiled = GL_FALSE;
  glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &compiled);
  if (compiled != GL_TRUE) {
    return make_error(Error::Kind::compile, where,
                      std::string(stage_name) + ": the GL driver's compiler rejected it:\n" +
                          shader_log(shader.get()));
  }
  return shader;
}

Error interface_error(const std::string& where, std::string message) {
  return make_error(Error::Kind::bad_input, where, std::move(message));
}

// Components of an input or output of type `type` (a scalar or a vector).
int components_of(GLint type) {
  switch (type) {
    case GL_FLOAT_VEC2:
    case GL_INT_VEC2:
    case GL_UNSIGNED_INT_VEC2:
      return 2;
    case GL_FLOAT_VEC3:
    case GL_INT_VEC3:
    case GL_UNSIGNED_INT_VEC3:
      return 3;
    case GL_FLOAT_VEC4:
    case GL_INT_VEC4:
    case GL_UNSIGNED_INT_VEC4:
      return 4;
    default:
      return 1;
  }
}

// A program resource (GL_PROGRAM_INPUT or GL_PROGRAM_OUTPUT) as GL reports it.
struct Resource {
  std::string name;
  GLint location = -1;
  int components = 0;
};

std::vector<Resource> active_resources(GLuint program, GLenum interface) {
  GLint count = 0;
  glGetProgramInterfaceiv(program, interface, GL_ACTIVE_RESOURCES, &count);
  std::vector<Resource> resources;
  for (GLint i = 0; i < count; ++i) {
    const GLuint index = static_cast<GLuint>(i);
    GLchar name[256];
    glGetProgramResourceName(program, interface, index, sizeof name, nullptr, name);
    const GLenum properties[] = {GL_LOCATION, GL_TYPE};
    GLint values[2] = {-1, 0};
    glGetProgramResourceiv(program, interface, index, 2, properties, 2, nullptr, values);
    if (std::string_view(name).starts_with("gl_")) continue;
    resources.push_back({name, values[0], components_of(values[1])});
  }
  return resources;
}

// The reflection's vertex inputs at the locations the engine binds its
// triangle to (the reflection's, or their order where it gives none).
GLuint input_location(const PassReflection& reflection, std::size_t i) {
  return reflection.vertex_inputs[i].location.value_or(static_cast<std::uint32_t>(i));
}

Status check_reflection_drawable(const PassReflection& reflection, const std::string& where,
                                 std::uint32_t position_components) {
  for (const VertexAttribute& input : reflection.vertex_inputs) {
    if (input.components != position_components || input.format != kPositionFormat) {
      return interface_error(where, "the reflection's vertex input '" + input.name + "' has " +
                                        std::to_string(input.components) + " " + input.format +
                                        " component(s); the GL engine draws this pass with " +
                                        std::to_string(position_components) +
                                        " GL_FLOAT components per vertex");
    }
  }
  if (reflection.render_targets.size() != 1) {
    return interface_error(where, "the reflection lists " +
                                      std::to_string(reflection.render_targets.size()) +
                                      " render targets; the GL engine draws into one");
  }
  return {};
}

Status check_inputs(GLuint program, const PassReflection& reflection, const std::string& where) {
  for (const Resource& active : active_resources(program, GL_PROGRAM_INPUT)) {
    const auto& inputs = reflection.vertex_inputs;
    const auto found = std::find_if(inputs.begin(), inputs.end(), [&](const VertexAttribute& a) {
      return a.name == active.name;
    });
    if (found == inputs.end()) {
      return interface_error(where, "vertex input '" + active.name +
                                        "' is active in the program but not in the reflection");
    }
    const GLuint location = input_location(reflection, std::size_t(found - inputs.begin()));
    if (active.location != GLint(location) || active.components != int(found->components)) {
      return interface_error(
          where, "vertex input '" + active.name + "' has " + std::to_string(active.components) +
                     " component(s) at location " + std::to_string(active.location) +
                     "; the reflection says " + std::to_string(found->components) +
                     " at location " + std::to_string(location));
    }
  }
  return {};
}

Status check_outputs(GLuint program, const PassReflection& reflection, const std::string& where) {
  const std::vector<Resource> outputs = active_resources(program, GL_PROGRAM_OUTPUT);
  for (const Resource& active : outputs) {
    const auto& targets = reflection.render_targets;
    if (std::none_of(targets.begin(), targets.end(),
                     [&](const RenderTarget& t) { return t.name == active.name; })) {
      return interface_error(where, "fragment output '" + active.name +
                                        "' is active in the program but not in the reflection");
    }
  }
  for (const RenderTarget& target : reflection.render_targets) {
    const auto active = std::find_if(outputs.begin(), outputs.end(),
                                     [&](const Resource& r) { return r.name == target.name; });
    if (active == outputs.end()) {
      return interface_error(where, "the fragment stage has no output '" + target.name +
                                        "', the reflection's render target " +
                                        std::to_string(target.index));
    }
    if (active->location != GLint(target.index)) {
      return interface_error(where, "fragment output '" + target.name + "' is at location " +
                                        std::to_string(active->location) +
                                        "; the reflection says " + std::to_string(target.index));
    }
    auto format = texel_format(target.format, where, "render target '" + target.name + "'");
    if (!format) return format.error();
    if (active->components < (*format)->channels) {
      return interface_error(where, "fragment output '" + target.name + "' has " +
                                        std::to_string(active->components) + " component(s); its " +
                                        target.format + " target takes " +
                                        std::to_string((*format)->channels));
    }
  }
  return {};
}

}  // namespace

Result<Program> build_program(std::string_view vertex_text, std::string_view fragment_text,
                              const PassReflection& reflection, const std::string& where,
                              std::uint32_t position_components) {
  PENUMBRA_TRY(check_reflection_drawable(reflection, where, position_components));
  auto vertex = compile(GL_VERTEX_SHADER, vertex_text, "vertex stage", where);
  if (!vertex) return vertex.error();
  auto fragment = compile(GL_FRAGMENT_SHADER, fragment_text, "fragment stage", where);
  if (!fragment) return fragment.error();
  Program program(glCreateProgram());
  glAttachShader(program.get(), vertex->get());
  glAttachShader(program.get(), fragment->get());
  // GLSL 3.30 may leave locations to the application: bind them by name.
  for (std::size_t i = 0; i < reflection.vertex_inputs.size(); ++i) {
    glBindAttribLocation(program.get(), input_location(reflection, i),
                         reflection.vertex_inputs[i].name.c_str());
  }
  for (const RenderTarget& target : reflection.render_targets) {
    glBindFragDataLocation(program.get(), target.index, target.name.c_str());
  }
  glLinkProgram(program.get());
  GLint linked = GL_FALSE;
  glGetProgramiv(program.get(), GL_LINK_STATUS, &linked);
  if (linked != GL_TRUE) {
    return make_error(
        Error::Kind::compile, where,
        "link: the GL driver could not link the stages:\n" + program_log(program.get()));
  }
  PENUMBRA_TRY(check_inputs(program.get(), reflection, where));
  PENUMBRA_TRY(check_outputs(program.get(), reflection, where));
  return program;
}

}  // namespace penumbra::gl
