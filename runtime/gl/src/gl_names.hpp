// Owning OpenGL object names for the objects one call creates. Each deletes
// its object when destroyed, so the engine's context must still be current
// then: every GlEngine call creates them inside its CurrentScope.
#pragma once

#include <utility>

#include "gl_api.hpp"

namespace penumbra::gl {

template <typename Delete>
class Name {
 public:
  Name() = default;
  explicit Name(GLuint name) : name_(name) {}
  Name(Name&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  Name& operator=(Name&& other) noexcept {
    std::swap(name_, other.name_);
    return *this;
  }
  Name(const Name&) = delete;
  Name& operator=(const Name&) = delete;
  ~Name() {
    if (name_ != 0) Delete{}(name_);
  }

  GLuint get() const { return name_; }

 private:
  GLuint name_ = 0;
};

struct DeleteShader {
  void operator()(GLuint name) const { glDeleteShader(name); }
};
struct DeleteProgram {
  void operator()(GLuint name) const { glDeleteProgram(name); }
};
struct DeleteTexture {
  void operator()(GLuint name) const { glDeleteTextures(1, &name); }
};
struct DeleteBuffer {
  void operator()(GLuint name) const { glDeleteBuffers(1, &name); }
};
struct DeleteFramebuffer {
  void operator()(GLuint name) const { glDeleteFramebuffers(1, &name); }
};
struct DeleteVertexArray {
  void operator()(GLuint name) const { glDeleteVertexArrays(1, &name); }
};
struct DeleteSampler {
  void operator()(GLuint name) const { glDeleteSamplers(1, &name); }
};

using Shader = Name<DeleteShader>;
using Program = Name<DeleteProgram>;
using Texture = Name<DeleteTexture>;
using Buffer = Name<DeleteBuffer>;
using Framebuffer = Name<DeleteFramebuffer>;
using VertexArray = Name<DeleteVertexArray>;
using Sampler = Name<DeleteSampler>;

// New objects of each kind (glCreate*: created and initialized at once).
inline Texture create_texture(GLenum target) {
  GLuint name = 0;
  glCreateTextures(target, 1, &name);
  return Texture(name);
}
inline Texture create_texture_2d() {
  return create_texture(GL_TEXTURE_2D);
}
inline Buffer create_buffer() {
  GLuint name = 0;
  glCreateBuffers(1, &name);
  return Buffer(name);
}
inline Framebuffer create_framebuffer() {
  GLuint name = 0;
  glCreateFramebuffers(1, &name);
  return Framebuffer(name);
}
inline VertexArray create_vertex_array() {
  GLuint name = 0;
  glCreateVertexArrays(1, &name);
  return VertexArray(name);
}
inline Sampler create_sampler() {
  GLuint name = 0;
  glCreateSamplers(1, &name);
  return Sampler(name);
}

}  // namespace penumbra::gl
