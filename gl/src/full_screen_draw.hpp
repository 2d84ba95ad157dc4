// One draw of a pass: ShadowParams and the samplers bound, the full-screen
// triangle drawn into one colour target.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "gl_names.hpp"
#include "pass_program.hpp"
#include "penumbra/support/param_block.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

// What the sampler `name` reads: a texture through a sampler object.
struct ImageSource {
  std::string_view name;
  GLuint texture = 0;
  GLuint sampler = 0;
};

struct DrawTarget {
  const Texture& texture;  // level 0 is drawn, width x height
  int width = 0;
  int height = 0;
};

// Sets `params` on the pass (bind_params), binds each of its active samplers
// to the source of that name, and draws one full-screen triangle into
// `target` with a viewport of its size. `what` names the draw in GL errors
// ("the minmax_reduce pass (level 3)"). Errors: bad_input from bind_params;
// internal when an active sampler has no source; device for an incomplete
// framebuffer or a GL error.
Status draw_full_screen(const PassProgram& pass, const ParamBlock& params,
                        std::span<const ImageSource> sources, const DrawTarget& target,
                        const std::string& what);

}  // namespace penumbra::gl
