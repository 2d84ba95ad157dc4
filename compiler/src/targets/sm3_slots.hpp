// Instruction slots of Shader Model 3 code, counted on the assembly that
// vkd3d-compiler disassembles from the d3dbc we ship (its d3d-asm output).
#pragma once

#include <string_view>

namespace penumbra {

// The instructions every ps_3_0 device executes in one invocation
// (D3DCAPS9 MaxPShaderInstructionsExecuted, at least 65,535).
inline constexpr long long kPs30MinimumExecuted = 65535;

// The slots every vs_3_0 and ps_3_0 device runs (D3DCAPS9
// MaxVertexShader30InstructionSlots / MaxPixelShader30InstructionSlots).
inline constexpr int kSm3MinimumSlots = 512;

// The instruction slots of `assembly`: every instruction but the version,
// declarations and constant definitions; flow control counts, and macros
// count as the instructions they expand to (the Direct3D 9 reference's slot
// counts: nrm 3, sincos 8, m4x4 4, ...).
int count_sm3_slots(std::string_view assembly);

// The slots of one line of that assembly (0 for what does not execute).
int sm3_line_slots(std::string_view line);

}  // namespace penumbra
