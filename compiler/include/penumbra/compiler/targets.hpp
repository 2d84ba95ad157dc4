// What the compiler makes of a target's traits (target_traits.hpp): the
// defines the shader source sees, its bytecode and the file names of its output.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "penumbra/model/model.hpp"
#include "penumbra/model/target_traits.hpp"
#include "penumbra/spirv/reflection.hpp"

namespace penumbra {

// `#define` lines for the target, included into every shader via variant.glsl.
std::string target_defines(Target target);

// The Direct3D bytecode a stage's HLSL text compiles to (vkd3d-compiler's
// terms), by the target's shader model: for hlsl_dx9, vs_3_0/ps_3_0 as
// d3dbc; for hlsl_dx10 and hlsl_dx11, vs_4_0/ps_4_0 and vs_5_0/ps_5_0 as
// dxbc-tpf.
struct BytecodeFormat {
  std::string profile;          // "vs_3_0", "ps_3_0", "vs_4_0", ..., "ps_5_0"
  std::string_view vkd3d_type;  // vkd3d-compiler's -b: "d3dbc" or "dxbc-tpf"
  std::string_view extension;   // ".d3dbc" or ".dxbc", replacing the text's ".hlsl"
};

// The target's bytecode for `stage`; none for a target that is not HLSL.
std::optional<BytecodeFormat> bytecode_format(Target target, ShaderStage stage);

// File name of a stage's output, e.g. "query.frag.spv", "query.frag", "query.frag.hlsl".
std::string output_file_name(Target target, std::string_view pass_file, ShaderStage stage);

}  // namespace penumbra
