#include "surface_pass.hpp"

#include <string>

#include "full_screen_draw.hpp"
#include "gl_check.hpp"
#include "param_binding.hpp"
#include "textures.hpp"

namespace penumbra::gl {

Status draw_triangles(const PassProgram& pass, const ParamBlock& params, PassInputs& inputs,
                      std::span<const std::array<float, 3>> triangles, const DrawTarget& target) {
  if (pass.reflection->vertex_inputs.size() != 1) {
    return make_error(Error::Kind::bad_input, pass.where,
                      "the reflection lists " +
                          std::to_string(pass.reflection->vertex_inputs.size()) +
                          " vertex inputs; a surface takes one, its position");
  }
  const int width = target.width;
  const int height = target.height;
  Texture depth = create_texture_2d();
  glTextureStorage2D(depth.get(), 1, GL_DEPTH_COMPONENT32F, width, height);
  auto framebuffer = framebuffer_for(pass, target.texture, "the " + pass.where, &depth);
  if (!framebuffer) return framebuffer.error();
  Buffer positions = create_buffer();
  glNamedBufferStorage(positions.get(), GLsizeiptr(triangles.size() * sizeof triangles[0]),
                       triangles.data(), 0);
  VertexArray layout = create_vertex_array();
  const GLuint location = pass.reflection->vertex_inputs.front().location.value_or(0);
  glVertexArrayVertexBuffer(layout.get(), 0, positions.get(), 0, sizeof triangles[0]);
  glVertexArrayAttribFormat(layout.get(), location, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(layout.get(), location, 0);
  glEnableVertexArrayAttrib(layout.get(), location);
  // Kept until the draw: the uniform buffers of the pass's blocks.
  auto param_buffers = bind_params(pass.program.get(), pass.bindings, params, pass.where);
  if (!param_buffers) return param_buffers.error();
  PENUMBRA_TRY(check_gl("setting up the " + pass.where));

  const ProgramInUse in_use(pass.program.get());
  PENUMBRA_TRY(bind_pass_textures(pass, inputs));
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer->get());
  glViewport(0, 0, width, height);
  // The nearest surface wins, as in an engine; both targets start at 1.
  constexpr GLfloat kOnes[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glClearNamedFramebufferfv(framebuffer->get(), GL_COLOR, 0, kOnes);
  glClearNamedFramebufferfv(framebuffer->get(), GL_DEPTH, 0, kOnes);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glBindVertexArray(layout.get());
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(triangles.size()));
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindVertexArray(0);
  return check_gl("drawing the " + pass.where);
}

}  // namespace penumbra::gl
