#include "gl_program.hpp"

#include <algorithm>
#include <charconv>
#include <string>
#include <vector>

namespace penumbra::gl {
namespace {

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
                       const PassRole& role) {
  Shader shader(glCreateShader(stage));
  const GLchar* source = text.data();
  const GLint length = static_cast<GLint>(text.size());
  glShaderSource(shader.get(), 1, &source, &length);
  glCompileShader(shader.get());
  GLint compiled = GL_FALSE;
  glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &compiled);
  if (compiled != GL_TRUE) {
    return make_error(Error::Kind::compile, std::string(role.where),
                      std::string(stage_name) + ": the GL driver's compiler rejected it:\n" +
                          shader_log(shader.get()));
  }
  return shader;
}

Error interface_error(const PassRole& role, std::string message) {
  return make_error(Error::Kind::bad_input, std::string(role.where), std::move(message));
}

// Every pass draws into an RG32F target: its output needs both channels.
constexpr int kTargetComponents = 2;

// Components of a fragment output of type `type` (a scalar or a vector).
int output_components(GLint type) {
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

// Every pass supplies one vec2 at location 0 and reads colour 0.
Status check_stage_interface(GLuint program, const PassRole& role) {
  GLint inputs = 0;
  glGetProgramiv(program, GL_ACTIVE_ATTRIBUTES, &inputs);
  bool has_position = false;
  for (GLint i = 0; i < inputs; ++i) {
    GLchar name[256];
    GLint size = 0;
    GLenum type = 0;
    glGetActiveAttrib(program, static_cast<GLuint>(i), sizeof name, nullptr, &size, &type, name);
    const std::string input(name);
    if (input.starts_with("gl_")) continue;
    if (input != "position" || type != GL_FLOAT_VEC2) {
      return interface_error(role, "vertex input '" + input + "' is not part of the " +
                                       std::string(role.where) +
                                       ", which supplies only 'position' (vec2, location 0)");
    }
    has_position = true;
  }
  const GLint location = glGetAttribLocation(program, "position");
  if (!has_position || location != 0) {
    return interface_error(
        role, has_position ? "vertex input 'position' is at location " + std::to_string(location) +
                                 "; the pass supplies it at location 0"
                           : "the vertex stage has no active input 'position' (vec2, location 0)");
  }
  const std::string name(role.output);
  const GLint output = glGetFragDataLocation(program, name.c_str());
  if (output != 0) {
    return interface_error(role, output < 0 ? "the fragment stage has no output '" + name + "'"
                                            : "fragment output '" + name + "' is at location " +
                                                  std::to_string(output) + "; the pass reads 0");
  }
  const GLuint index = glGetProgramResourceIndex(program, GL_PROGRAM_OUTPUT, name.c_str());
  const GLenum property = GL_TYPE;
  GLint type = 0;
  glGetProgramResourceiv(program, GL_PROGRAM_OUTPUT, index, 1, &property, 1, nullptr, &type);
  const int components = output_components(type);
  if (components < kTargetComponents) {
    return interface_error(role, "fragment output '" + name + "' has " +
                                     std::to_string(components) + " component(s); the " +
                                     std::string(role.where) + "'s RG32F target takes " +
                                     std::to_string(kTargetComponents));
  }
  return {};
}

}  // namespace

Result<Program> build_program(std::string_view vertex_text, std::string_view fragment_text,
                              const PassRole& role) {
  auto vertex = compile(GL_VERTEX_SHADER, vertex_text, "vertex stage", role);
  if (!vertex) return vertex.error();
  auto fragment = compile(GL_FRAGMENT_SHADER, fragment_text, "fragment stage", role);
  if (!fragment) return fragment.error();
  Program program(glCreateProgram());
  glAttachShader(program.get(), vertex->get());
  glAttachShader(program.get(), fragment->get());
  // GLSL 3.30 may leave locations to the application: bind them by name.
  glBindAttribLocation(program.get(), 0, "position");
  glBindFragDataLocation(program.get(), 0, std::string(role.output).c_str());
  glLinkProgram(program.get());
  GLint linked = GL_FALSE;
  glGetProgramiv(program.get(), GL_LINK_STATUS, &linked);
  if (linked != GL_TRUE) {
    return make_error(
        Error::Kind::compile, std::string(role.where),
        "link: the GL driver could not link the stages:\n" + program_log(program.get()));
  }
  PENUMBRA_TRY(check_stage_interface(program.get(), role));
  return program;
}

int glsl_version(std::string_view text) {
  const std::size_t start = text.find_first_not_of(" \t\r\n");
  constexpr std::string_view kDirective = "#version";
  if (start == std::string_view::npos || text.substr(start, kDirective.size()) != kDirective) {
    return 0;
  }
  std::string_view rest = text.substr(start + kDirective.size());
  rest.remove_prefix(std::min(rest.find_first_not_of(" \t"), rest.size()));
  int version = 0;
  std::from_chars(rest.data(), rest.data() + rest.size(), version);
  return version;
}

}  // namespace penumbra::gl
