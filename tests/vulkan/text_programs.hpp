// The runtime tests' programs from the default variants' emitted text:
// each target's text compiled by glslang's front end as the runtime
// compiles a library's (compile_target_text), with the target's reflection
// record (compile_pass); and single stages in the shapes of the text
// targets, compiled from shaders/ at build time, for reflect()'s tests.
#pragma once

#include <string>
#include <string_view>

#include "penumbra/vulkan/program.hpp"

namespace penumbra::test {

// shaders/<name>.spv with its reflect() record; fails the test if either fails.
StageCode reflected_stage(const std::string& name);

// The default variant `variant`'s `pass` for `target`, ready to run: the
// SPIR-V as built for spirv, else its text compiled by the target's front
// end; with its reflection record. Fails the test if any step fails.
PassProgram text_program(const std::string& variant, PassKind pass, Target target);

}  // namespace penumbra::test
