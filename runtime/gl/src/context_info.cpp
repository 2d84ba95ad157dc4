#include "context_info.hpp"

#include "gl_api.hpp"

namespace penumbra::gl {
namespace {

std::string gl_string(GLenum name) {
  const GLubyte* value = glGetString(name);
  return value == nullptr ? std::string() : std::string(reinterpret_cast<const char*>(value));
}

}  // namespace

GlInfo current_context_info() {
  return {gl_string(GL_RENDERER), gl_string(GL_VERSION), gl_string(GL_SHADING_LANGUAGE_VERSION)};
}

}  // namespace penumbra::gl
