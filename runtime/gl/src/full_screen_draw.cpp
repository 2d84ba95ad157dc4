#include "full_screen_draw.hpp"

#include <cstdio>
#include <vector>

#include "gl_check.hpp"
#include "param_binding.hpp"
#include "penumbra/support/full_screen_triangle.hpp"
#include "textures.hpp"

namespace penumbra::gl {
namespace {

struct Geometry {
  Buffer vertices;
  VertexArray layout;
};

// The triangle's two floats per vertex at each of the reflection's vertex
// inputs (build_program admitted only 2-float inputs).
Geometry full_screen_triangle(const PassReflection& reflection) {
  Geometry geometry{create_buffer(), create_vertex_array()};
  glNamedBufferStorage(geometry.vertices.get(), sizeof kFullScreenTriangle,
                       kFullScreenTriangle.data(), 0);
  glVertexArrayVertexBuffer(geometry.layout.get(), 0, geometry.vertices.get(), 0,
                            2 * sizeof(float));
  for (std::size_t i = 0; i < reflection.vertex_inputs.size(); ++i) {
    const GLuint location =
        reflection.vertex_inputs[i].location.value_or(static_cast<std::uint32_t>(i));
    glVertexArrayAttribFormat(geometry.layout.get(), location, 2, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(geometry.layout.get(), location, 0);
    glEnableVertexArrayAttrib(geometry.layout.get(), location);
  }
  return geometry;
}

}  // namespace

Result<Framebuffer> framebuffer_for(const PassProgram& pass, const Texture& target,
                                    const std::string& what, const Texture* depth) {
  Framebuffer framebuffer = create_framebuffer();
  const GLenum attachment = GL_COLOR_ATTACHMENT0 + pass.reflection->render_targets.front().index;
  glNamedFramebufferTexture(framebuffer.get(), attachment, target.get(), 0);
  if (depth) glNamedFramebufferTexture(framebuffer.get(), GL_DEPTH_ATTACHMENT, depth->get(), 0);
  glNamedFramebufferDrawBuffer(framebuffer.get(), attachment);
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer.get(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", status);
    return make_error(Error::Kind::device, "glCheckNamedFramebufferStatus",
                      "the " + std::string(pass.target_format->name()) + " target of " + what +
                          (depth ? " with its depth buffer" : "") + " is not renderable: status " +
                          code);
  }
  return framebuffer;
}

Status bind_pass_textures(const PassProgram& pass, PassInputs& inputs) {
  for (std::size_t i = 0; i < pass.bindings.textures.size(); ++i) {
    const TextureSlot& slot = pass.bindings.textures[i];
    auto texture = inputs.texture_for(slot.texture, *slot.binding, pass.where);
    if (!texture) return texture.error();
    glBindTextureUnit(slot.unit, *texture);
    glBindSampler(slot.unit, pass.samplers[i].get());
  }
  return {};
}

Result<Texture> create_pass_target(const PassProgram& pass, int width, int height,
                                   const std::string& what) {
  return create_target(*pass.target_format, width, height, what);
}

Status draw_full_screen(const PassProgram& pass, const ParamBlock& params, PassInputs& inputs,
                        const DrawTarget& target, const std::string& what) {
  // Kept until the draw: the uniform buffers of the pass's blocks.
  auto param_buffers = bind_params(pass.program.get(), pass.bindings, params, pass.where);
  if (!param_buffers) return param_buffers.error();
  auto framebuffer = framebuffer_for(pass, target.texture, what);
  if (!framebuffer) return framebuffer.error();
  const Geometry geometry = full_screen_triangle(*pass.reflection);
  PENUMBRA_TRY(check_gl("setting up " + what));

  // Depth test and culling stay off, and blending but for pass_through_blend:
  // this context enables none of them otherwise.
  const ProgramInUse in_use(pass.program.get());
  PENUMBRA_TRY(bind_pass_textures(pass, inputs));
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer->get());
  glViewport(0, 0, target.width, target.height);
  glBindVertexArray(geometry.layout.get());
  if (target.pass_through_blend) {
    // A new target's texels are undefined; the blend must read finite ones.
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, zero);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);
  }
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_BLEND);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindVertexArray(0);
  return check_gl("drawing " + what);
}

}  // namespace penumbra::gl
