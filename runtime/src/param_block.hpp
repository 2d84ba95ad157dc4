// Packing a ParamBlock into the bytes of a uniform block holding ShadowParams'
// members (ShadowParams itself, or glslang's global block).
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "binding_plan.hpp"
#include "penumbra/runtime/program.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::detail {

// SPIRV-Cross's Direct3D 9 half-pixel constant in HLSL vertex shaders.
inline constexpr std::string_view kHalfPixel = "gl_HalfPixel";

// `layout.size` bytes, each member at its reflected offset holding the first
// size/4 floats of the ParamBlock entry under its param_block_key (all four
// for the interface's vec4 members), and gl_HalfPixel zero; bytes no member
// covers are zero. A member the ParamBlock lacks, or one that is not 1 to 4
// floats, is a bad_input Error (where = `pass`) naming it.
Result<std::vector<std::byte>> pack_params(const ParamsLayout& layout, const ParamBlock& params,
                                           std::string_view pass);

}  // namespace penumbra::detail
