// Setting ShadowParams from a name -> vec4 map, by member name, in both of
// the forms the GLSL targets emit.
#pragma once

#include "gl_names.hpp"
#include "penumbra/support/param_block.hpp"
#include "penumbra/support/result.hpp"
#include "program_interface.hpp"

namespace penumbra::gl {

// Plain uniforms (GLSL 3.30's `uniform ShadowParams params;`): each member is
// set at its location. Uniform block (GLSL 4.50): a uniform buffer of the
// block's size is filled at each member's queried offset and bound at the
// block's binding. Returns that buffer (empty for plain uniforms); keep it
// until the draw. Errors (bad_input, `where` = role.where): a member without
// a value in `params`.
Result<Buffer> bind_params(GLuint program, const ProgramInterface& iface, const ParamBlock& params,
                           const PassRole& role);

}  // namespace penumbra::gl
