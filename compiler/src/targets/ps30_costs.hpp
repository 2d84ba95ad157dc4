// The ps_3_0 instruction slots one SPIR-V instruction costs once FXC has
// turned it into Shader Model 3.0 assembly (the slot column of the ps_3_0
// instruction table). Calls, loops and branches are costed by the caller.
#pragma once

#include "spirv/module.hpp"

namespace penumbra {

// Slots of the flow-control instructions around branches and rolled loops.
inline constexpr int kPs30IfSlots = 3;       // if_comp / if pred
inline constexpr int kPs30ElseSlots = 1;     // else
inline constexpr int kPs30EndifSlots = 1;    // endif
inline constexpr int kPs30LoopSlots = 3;     // loop aL, i# / rep i#
inline constexpr int kPs30EndloopSlots = 2;  // endloop / endrep
inline constexpr int kPs30BreakSlots = 3;    // break_comp

int ps30_instruction_slots(const SpirvModule& module, const SpvInstruction& in);

}  // namespace penumbra
