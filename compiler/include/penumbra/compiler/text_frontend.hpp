// Compiling a target's emitted text back into Vulkan SPIR-V with glslang's
// GLSL or HLSL front end, so that the runtime executes the text an engine
// would ship rather than the SPIR-V it was cross-compiled from.
// Per target options and shims: docs/frontends.md.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/compiler/reflection.hpp"
#include "penumbra/model/model.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

// glsl330's loose uniforms (`uniform ShadowParams params;`) are gathered by
// glslang into one uniform block of this name, set 0; a loose struct becomes
// a struct member of it (`params`). hlsl_dx9's loose uniforms are gathered
// into glslang's HLSL block "$Global" instead (its name is fixed by glslang).
inline constexpr std::string_view kLooseUniformBlockName = "PenumbraLooseUniforms";

// HLSL s# registers are bound at this Vulkan binding plus the register
// number, so that a sampler never shares a binding with the t# texture of
// the same number. b# and t# registers keep their numbers.
inline constexpr std::uint32_t kHlslSamplerBindingBase = 16;

// hlsl_dx9 vertex shaders: the $Global block (D3D9's vertex constant file,
// separate from the pixel shader's) is bound here rather than at 0, past
// every t# and s# binding, so no texture of the pass shares it.
inline constexpr std::uint32_t kDx9VertexConstantsBinding = 2 * kHlslSamplerBindingBase;

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
