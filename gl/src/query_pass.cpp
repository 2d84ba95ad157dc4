#include "query_pass.hpp"

#include <cstdio>
#include <vector>

#include "gl_check.hpp"
#include "gl_program.hpp"
#include "penumbra/support/full_screen_triangle.hpp"
#include "program_interface.hpp"
#include "sampler_units.hpp"
#include "textures.hpp"

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

Result<Framebuffer> framebuffer_for(const Texture& target) {
  Framebuffer framebuffer = create_framebuffer();
  glNamedFramebufferTexture(framebuffer.get(), GL_COLOR_ATTACHMENT0, target.get(), 0);
  glNamedFramebufferDrawBuffer(framebuffer.get(), GL_COLOR_ATTACHMENT0);
  glNamedFramebufferReadBuffer(framebuffer.get(), GL_COLOR_ATTACHMENT0);
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer.get(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", status);
    return make_error(Error::Kind::device, "glCheckNamedFramebufferStatus",
                      std::string("the R32F visibility target is not renderable: status ") + code);
  }
  return framebuffer;
}

// The depth texture goes to shadow_depth and shadow_cmp, each with its own
// sampler object; the receivers to `receivers`.
void bind_textures(const std::vector<SamplerUnit>& units, const SamplerObjects& samplers,
                   const Texture& depth, const Texture& receivers) {
  for (const SamplerUnit& unit : units) {
    const bool is_receivers = unit.name == "receivers";
    glBindTextureUnit(unit.unit, is_receivers ? receivers.get() : depth.get());
    glBindSampler(unit.unit, unit.name == "shadow_cmp" ? samplers.compare : samplers.point);
  }
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

Result<FloatImage> run_query_pass(const SamplerObjects& samplers, const QueryInputs& inputs) {
  PENUMBRA_TRY(check_query_inputs(inputs.normalized_depth, inputs.receivers));
  auto program = build_query_program(inputs.vertex_text, inputs.fragment_text);
  if (!program) return program.error();
  auto iface = reflect_program(program->get());
  if (!iface) return iface.error();
  auto units = assign_sampler_units(program->get(), *iface, glsl_version(inputs.fragment_text));
  if (!units) return units.error();
  auto params = bind_params(program->get(), *iface, inputs.params);
  if (!params) return params.error();
  PENUMBRA_TRY(check_gl("binding the query program's uniforms"));

  auto depth = upload_depth(inputs.normalized_depth);
  if (!depth) return depth.error();
  auto receivers = upload_receivers(inputs.receivers);
  if (!receivers) return receivers.error();
  const int width = inputs.receivers.width;
  const int height = inputs.receivers.height;
  auto target = create_visibility_target(width, height);
  if (!target) return target.error();
  auto framebuffer = framebuffer_for(*target);
  if (!framebuffer) return framebuffer.error();
  const Geometry geometry = full_screen_triangle();

  FloatImage visibility(width, height, 1);
  {
    // Depth test, blending and culling stay off: this context never enables them.
    const ProgramInUse in_use(program->get());
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer->get());
    glViewport(0, 0, width, height);
    glBindVertexArray(geometry.layout.get());
    bind_textures(*units, samplers, *depth, *receivers);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    PENUMBRA_TRY(check_gl("drawing the query pass"));
    // Window row 0 is the contract's row j = 0 and glReadPixels returns it first.
    glReadPixels(0, 0, width, height, GL_RED, GL_FLOAT, visibility.data.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindVertexArray(0);
  }
  PENUMBRA_TRY(check_gl("reading back the visibility target"));
  return visibility;
}

}  // namespace penumbra::gl
