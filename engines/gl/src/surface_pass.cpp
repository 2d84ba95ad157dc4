#include "surface_pass.hpp"

#include <string>

#include "full_screen_draw.hpp"
#include "gl_check.hpp"
#include "minmax_mip.hpp"
#include "param_binding.hpp"
#include "pass_program.hpp"
#include "textures.hpp"

namespace penumbra::gl {
namespace {

constexpr const char* kWhere = "surface pass";

}  // namespace

Result<FloatImage> run_surface_pass(const GlPass& surface,
                                    std::span<const std::array<float, 3>> triangles,
                                    const FloatImage& normalized_depth, int width, int height,
                                    const ParamBlock& params, DepthFormat map_format,
                                    const std::optional<GlMinmaxPasses>& minmax) {
  if (triangles.size() % 3 != 0) {
    return make_error(Error::Kind::bad_input, kWhere,
                      std::to_string(triangles.size()) +
                          " vertices are not a whole number of triangles (a triangle list)");
  }
  if (surface.reflection.vertex_inputs.size() != 1) {
    return make_error(Error::Kind::bad_input, kWhere,
                      "the reflection lists " +
                          std::to_string(surface.reflection.vertex_inputs.size()) +
                          " vertex inputs; a surface takes one, its position");
  }
  PENUMBRA_TRY(check_shadow_map(normalized_depth));
  auto pass = prepare_program(surface, kWhere, 3);
  if (!pass) return pass.error();
  PassInputs inputs;
  inputs.give(TextureId::shadow_depth, normalized_depth, map_format);
  inputs.give(TextureId::shadow_cmp, normalized_depth, map_format);
  PENUMBRA_TRY_ASSIGN(const std::optional<MinmaxMip> mip,
                      give_minmax_mip(*pass, minmax, inputs,
                                      {normalized_depth.width, normalized_depth.height}, params));

  auto colour = create_pass_target(*pass, width, height, "the surface pass's target");
  if (!colour) return colour.error();
  Texture depth = create_texture_2d();
  glTextureStorage2D(depth.get(), 1, GL_DEPTH_COMPONENT32F, width, height);
  auto framebuffer = framebuffer_for(*pass, *colour, "the surface pass", &depth);
  if (!framebuffer) return framebuffer.error();
  Buffer positions = create_buffer();
  glNamedBufferStorage(positions.get(), GLsizeiptr(triangles.size() * sizeof triangles[0]),
                       triangles.data(), 0);
  VertexArray layout = create_vertex_array();
  const GLuint location = surface.reflection.vertex_inputs.front().location.value_or(0);
  glVertexArrayVertexBuffer(layout.get(), 0, positions.get(), 0, sizeof triangles[0]);
  glVertexArrayAttribFormat(layout.get(), location, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(layout.get(), location, 0);
  glEnableVertexArrayAttrib(layout.get(), location);
  // Kept until the draw: the uniform buffers of the pass's blocks.
  auto param_buffers = bind_params(pass->program.get(), pass->bindings, params, pass->where);
  if (!param_buffers) return param_buffers.error();
  PENUMBRA_TRY(check_gl("setting up the surface pass"));

  const ProgramInUse in_use(pass->program.get());
  PENUMBRA_TRY(bind_pass_textures(*pass, inputs));
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
  PENUMBRA_TRY(check_gl("drawing the surface pass"));
  return read_texture(*colour, *pass->target_format, 0, width, height, "the surface pass's target");
}

}  // namespace penumbra::gl
