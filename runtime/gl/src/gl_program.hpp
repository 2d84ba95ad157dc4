// Compiling and linking a pass from GLSL text, as a GL engine does: the
// driver's own compiler, its logs turned into errors, and the stages'
// interface (vertex inputs, fragment outputs) placed and checked by the
// pass's reflection.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "gl_names.hpp"
#include "penumbra/model/target_reflection.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::gl {

// Compiles both stages and links them. Before linking, each of the
// reflection's vertex inputs is bound to its location and each render
// target's output to its colour index (shaders with explicit locations keep
// theirs); afterwards every active input and output must be in the
// reflection at that place. Every error has `where`. Errors: compile (the
// message names the stage, or the link, and holds the driver's log);
// bad_input when the program and the reflection disagree (an active input or
// output the reflection lacks, another location, a render target the
// program does not write, an output with fewer components than its target's
// format), or the reflection asks for what the engine cannot draw (a vertex
// input other than one of `position_components` floats: 2 for its
// full-screen triangle, 3 for an engine's surfaces; other than one render
// target).
Result<Program> build_program(std::string_view vertex_text, std::string_view fragment_text,
                              const PassReflection& reflection, const std::string& where,
                              std::uint32_t position_components);

}  // namespace penumbra::gl
