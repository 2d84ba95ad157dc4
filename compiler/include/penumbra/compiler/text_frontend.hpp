// Compiling a target's emitted text back into Vulkan SPIR-V with glslang's
// GLSL or HLSL front end, so that the runtime executes the text an engine
// would ship rather than the SPIR-V it was cross-compiled from.
// Per target options and shims: docs/frontends.md.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/model/model.hpp"
#include "penumbra/spirv/reflection.hpp"
#include "penumbra/spirv/text_bindings.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

struct FrontEndResult {
  std::vector<std::uint32_t> spirv;  // Vulkan 1.0 SPIR-V; passes spirv-val
  std::string front_end;             // e.g. "glslang HLSL SM4"
  std::vector<std::string> shims;    // text rewrites that changed this text, in order; often none
};

// Compiles `text`, the emitted source of `target` for `stage`, with glslang
// in process. Errors: bad_input for Target::spirv (not text); compile when
// the front end rejects the text or its SPIR-V fails validation, naming the
// target and `name` (the file, in messages).
Result<FrontEndResult> compile_target_text(Target target, ShaderStage stage, std::string_view text,
                                           std::string_view name);

}  // namespace penumbra
