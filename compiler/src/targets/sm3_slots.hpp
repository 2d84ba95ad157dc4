// Instruction slots of Shader Model 3 code, counted on the assembly that
// vkd3d-compiler disassembles from the d3dbc we ship (its d3d-asm output).
#pragma once

#include <string_view>

namespace penumbra {

// The slots every vs_3_0 and ps_3_0 device runs (D3DCAPS9
// MaxVertexShader30InstructionSlots / MaxPixelShader30InstructionSlots).
inline constexpr int kSm3MinimumSlots = 512;

// The instruction slots of `assembly`: every instruction but the version,
// declarations and constant definitions; flow control counts, and macros
// count as the instructions they expand to (the Direct3D 9 reference's slot
// counts: nrm 3, sincos 8, m4x4 4, ...).
int count_sm3_slots(std::string_view assembly);

}  // namespace penumbra
