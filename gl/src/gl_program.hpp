// Compiling and linking a query pass from GLSL text, as a GL engine does:
// the driver's own compiler, its logs turned into errors.
#pragma once

#include <string_view>

#include "gl_names.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

// Compiles both stages and links them. The vertex input `position` is bound
// to location 0 and the fragment output `visibility` to colour 0 before
// linking (shaders with explicit locations keep theirs), and both are checked
// afterwards. Errors: compile (`where` = "vertex stage", "fragment stage" or
// "link", the message holds the driver's log); bad_input when `position`
// (vec2, location 0) or `visibility` (colour 0) is missing or elsewhere, or
// the vertex stage has another input.
Result<Program> build_query_program(std::string_view vertex_text, std::string_view fragment_text);

// The number N of the text's "#version N" line (330, 450), or 0 without one.
int glsl_version(std::string_view text);

}  // namespace penumbra::gl
