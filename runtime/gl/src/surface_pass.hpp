// An engine's own program drawing its geometry with a depth buffer of its
// own, its fragment stage calling a variant's function form
// (docs/function-form.md), which reads the shadow map.
#pragma once

#include <array>
#include <span>

#include "full_screen_draw.hpp"
#include "pass_inputs.hpp"
#include "pass_program.hpp"
#include "penumbra/support/param_block.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

// Draws `triangles` (a triangle list, 3 floats per vertex at the
// reflection's one vertex input, no culling) into `target` with a
// GL_DEPTH_COMPONENT32F depth buffer of the target's size (both cleared to
// 1.0, depth test LESS), `params` set and each texture `pass` samples
// bound to what `inputs` supplies. Errors: bad_input for another vertex
// input count; those of bind_params and `inputs`; device for a GL error.
Status draw_triangles(const PassProgram& pass, const ParamBlock& params, PassInputs& inputs,
                      std::span<const std::array<float, 3>> triangles, const DrawTarget& target);

}  // namespace penumbra::gl
