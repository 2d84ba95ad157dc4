// One draw of a pass: ShadowParams and the textures bound by the pass's
// reflection, the full-screen triangle drawn into one colour target.
#pragma once

#include <string>

#include "gl_names.hpp"
#include "pass_inputs.hpp"
#include "pass_program.hpp"
#include "penumbra/support/param_block.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

struct DrawTarget {
  const Texture& texture;  // level 0 is drawn, width x height, in the pass's target format
  int width = 0;
  int height = 0;
  // Blend ONE, ZERO: the target gets what the shader writes, as with blending
  // off, but llvmpipe then compiles one fragment function for the draw
  // instead of two (whole tiles and tile edges). Every pass target is float,
  // and is cleared to 0 first, so that the blend reads finite texels.
  bool pass_through_blend = false;
};

// glUseProgram for one draw; a program in use outlives glDeleteProgram.
class ProgramInUse {
 public:
  explicit ProgramInUse(GLuint program) { glUseProgram(program); }
  ProgramInUse(const ProgramInUse&) = delete;
  ProgramInUse& operator=(const ProgramInUse&) = delete;
  ~ProgramInUse() { glUseProgram(0); }
};

// A framebuffer drawing into `target` at the attachment of `pass`'s render
// target, with `depth` (a depth texture) as its depth buffer where given.
// Errors (device, naming `what`): it is incomplete.
Result<Framebuffer> framebuffer_for(const PassProgram& pass, const Texture& target,
                                    const std::string& what, const Texture* depth = nullptr);

// Binds each texture `pass` samples to what `inputs` supplies for it, with
// its sampler object. Errors: `inputs`'.
Status bind_pass_textures(const PassProgram& pass, PassInputs& inputs);

// A new target for `pass`: its render target's format, width x height.
Result<Texture> create_pass_target(const PassProgram& pass, int width, int height,
                                   const std::string& what);

// Sets `params` on the pass (bind_params), binds each texture it samples to
// what `inputs` supplies for it with its sampler object, and draws one
// full-screen triangle (at each of the reflection's vertex inputs) into
// `target` with a viewport of its size. `what` names the draw in GL errors
// ("the minmax_reduce pass (min-max level 3)"). Errors: bad_input from
// bind_params and `inputs`; device for an incomplete framebuffer or a GL
// error.
Status draw_full_screen(const PassProgram& pass, const ParamBlock& params, PassInputs& inputs,
                        const DrawTarget& target, const std::string& what);

}  // namespace penumbra::gl
