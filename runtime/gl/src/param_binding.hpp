// Setting ShadowParams from a name -> vec4 map, by the parameter each
// reflected constant carries, in both of the forms the GLSL targets emit.
#pragma once

#include <string>
#include <vector>

#include "gl_names.hpp"
#include "penumbra/support/param_block.hpp"
#include "penumbra/support/result.hpp"
#include "reflected_bindings.hpp"

namespace penumbra::gl {

// Loose uniforms (glsl330's "params.light") are set at their locations. Each
// uniform block (glsl450's ShadowParams) gets a buffer of the reflection's
// size, filled at the reflection's member offsets and bound at its binding.
// Returns those buffers; keep them until the draw. Errors (bad_input,
// `where`): a constant the program uses whose parameter has no value in
// `params`.
Result<std::vector<Buffer>> bind_params(GLuint program, const PassBindings& bindings,
                                        const ParamBlock& params, const std::string& where);

}  // namespace penumbra::gl
