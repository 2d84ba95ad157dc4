// Shaders compiled into a program by `penumbra embed` (penumbra::shaders,
// docs/embedding.md) as programs the engine runs.
#pragma once

#include "penumbra/shaders/library.hpp"
#include "penumbra/support/result.hpp"
#include "penumbra/vulkan/program.hpp"

namespace penumbra {

// A spirv program of an embedded library (shaders::Library::find) ready to
// run: both stages' words with their reflect() record, and the pass's
// reflection record parsed; what load_executable gives for the same pass of
// the library it was embedded from. Errors: bad_input for a program of
// another target (its text needs a front end: compile_target_text) or a
// reflection that is not a pass's record; compile when a stage's words
// cannot be reflected.
Result<PassProgram> embedded_program(const shaders::Program& program);

}  // namespace penumbra
