#include "full_screen_draw.hpp"

#include <cstdio>

#include "gl_check.hpp"
#include "param_binding.hpp"
#include "penumbra/support/full_screen_triangle.hpp"

namespace penumbra::gl {
namespace {

struct Geometry {
  Buffer vertices;
  VertexArray layout;
};

// `position` at attribute location 0: two floats per vertex.
Geometry full_screen_triangle() {
  Geometry geometry{create_buffer(), create_vertex_array()};
  glNamedBufferStorage(geometry.vertices.get(), sizeof kFullScreenTriangle,
                       kFullScreenTriangle.data(), 0);
  glVertexArrayVertexBuffer(geometry.layout.get(), 0, geometry.vertices.get(), 0,
                            2 * sizeof(float));
  glVertexArrayAttribFormat(geometry.layout.get(), 0, 2, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(geometry.layout.get(), 0, 0);
  glEnableVertexArrayAttrib(geometry.layout.get(), 0);
  return geometry;
}

Result<Framebuffer> framebuffer_for(const Texture& target, const std::string& what) {
  Framebuffer framebuffer = create_framebuffer();
  glNamedFramebufferTexture(framebuffer.get(), GL_COLOR_ATTACHMENT0, target.get(), 0);
  glNamedFramebufferDrawBuffer(framebuffer.get(), GL_COLOR_ATTACHMENT0);
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer.get(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", status);
    return make_error(Error::Kind::device, "glCheckNamedFramebufferStatus",
                      "the RG32F target of " + what + " is not renderable: status " + code);
  }
  return framebuffer;
}

Status bind_samplers(const PassProgram& pass, std::span<const ImageSource> sources) {
  for (const SamplerUnit& unit : pass.units) {
    const ImageSource* source = nullptr;
    for (const ImageSource& candidate : sources) {
      if (candidate.name == unit.name) source = &candidate;
    }
    if (source == nullptr) {
      return make_error(Error::Kind::internal, std::string(pass.role->where),
                        "no image to bind to the active sampler '" + unit.name + "'");
    }
    glBindTextureUnit(unit.unit, source->texture);
    glBindSampler(unit.unit, source->sampler);
  }
  return {};
}

// glUseProgram for one draw; a program in use outlives glDeleteProgram.
class ProgramInUse {
 public:
  explicit ProgramInUse(GLuint program) { glUseProgram(program); }
  ProgramInUse(const ProgramInUse&) = delete;
  ProgramInUse& operator=(const ProgramInUse&) = delete;
  ~ProgramInUse() { glUseProgram(0); }
};

}  // namespace

Status draw_full_screen(const PassProgram& pass, const ParamBlock& params,
                        std::span<const ImageSource> sources, const DrawTarget& target,
                        const std::string& what) {
  // Kept until the draw: the uniform buffer of a ShadowParams block.
  auto param_buffer = bind_params(pass.program.get(), pass.iface, params, *pass.role);
  if (!param_buffer) return param_buffer.error();
  auto framebuffer = framebuffer_for(target.texture, what);
  if (!framebuffer) return framebuffer.error();
  const Geometry geometry = full_screen_triangle();
  PENUMBRA_TRY(check_gl("setting up " + what));

  // Depth test, blending and culling stay off: this context never enables them.
  const ProgramInUse in_use(pass.program.get());
  PENUMBRA_TRY(bind_samplers(pass, sources));
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer->get());
  glViewport(0, 0, target.width, target.height);
  glBindVertexArray(geometry.layout.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindVertexArray(0);
  return check_gl("drawing " + what);
}

}  // namespace penumbra::gl
