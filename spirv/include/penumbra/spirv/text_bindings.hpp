// Where glslang's front ends put what a target's text declares without a
// Vulkan binding (docs/frontends.md): the names and bindings the compiler's
// front ends choose and the engines look up when they bind text-compiled
// SPIR-V by a target's rules.
#pragma once

#include <cstdint>
#include <string_view>

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

}  // namespace penumbra
