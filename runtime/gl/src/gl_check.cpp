#include "gl_check.hpp"

#include <cstdio>
#include <string>
#include <utility>

#include "gl_api.hpp"

namespace penumbra::gl {
namespace {

std::string error_name(GLenum error) {
  static constexpr std::pair<GLenum, const char*> kNames[] = {
      {GL_INVALID_ENUM, "GL_INVALID_ENUM"},
      {GL_INVALID_VALUE, "GL_INVALID_VALUE"},
      {GL_INVALID_OPERATION, "GL_INVALID_OPERATION"},
      {GL_INVALID_FRAMEBUFFER_OPERATION, "GL_INVALID_FRAMEBUFFER_OPERATION"},
      {GL_OUT_OF_MEMORY, "GL_OUT_OF_MEMORY"},
      {GL_STACK_UNDERFLOW, "GL_STACK_UNDERFLOW"},
      {GL_STACK_OVERFLOW, "GL_STACK_OVERFLOW"},
      {GL_CONTEXT_LOST, "GL_CONTEXT_LOST"},
  };
  const char* name = "unknown GL error";
  for (const auto& [code, known] : kNames) {
    if (code == error) name = known;
  }
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", error);
  return std::string(name) + " (" + code + ")";
}

}  // namespace

Status check_gl(std::string_view what) {
  std::string errors;
  // Bounded: a lost context may report GL_CONTEXT_LOST on every call.
  for (int i = 0; i < 8; ++i) {
    const GLenum error = glGetError();
    if (error == GL_NO_ERROR) break;
    errors += (errors.empty() ? "" : ", ") + error_name(error);
  }
  if (errors.empty()) return {};
  return make_error(Error::Kind::device, "OpenGL", std::string(what) + " failed: " + errors);
}

}  // namespace penumbra::gl
