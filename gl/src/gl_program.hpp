// Compiling and linking a pass from GLSL text, as a GL engine does: the
// driver's own compiler, its logs turned into errors.
#pragma once

#include <string_view>

#include "gl_names.hpp"
#include "pass_role.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

// Compiles both stages and links them. The vertex input `position` is bound
// to location 0 and the fragment output role.output to colour 0 before
// linking (shaders with explicit locations keep theirs), and both are checked
// afterwards. Every error has `where` = role.where. Errors: compile (the
// message names the stage, or the link, and holds the driver's log);
// bad_input when `position` (vec2, location 0) or the output (colour 0) is
// missing or elsewhere, the output has fewer than 2 components (every pass
// draws into an RG32F target), or the vertex stage has another input.
Result<Program> build_program(std::string_view vertex_text, std::string_view fragment_text,
                              const PassRole& role);

// The number N of the text's "#version N" line (330, 450), or 0 without one.
int glsl_version(std::string_view text);

}  // namespace penumbra::gl
