// An estimate of the ps_3_0 instruction slots FXC would use for a fragment
// shader, made from its SPIR-V. The model (docs/targets.md) costs each
// instruction as the ps_3_0 instruction it becomes, inlines every call and
// unrolls the loops that ps_3_0 cannot keep rolled.
#pragma once

#include "spirv/module.hpp"

namespace penumbra {

// Every ps_3_0 device runs shaders of this many slots; many allow more.
inline constexpr int kPs30MinimumSlots = 512;

// Estimated slots of the module's entry point; 0 when it has none.
int estimate_ps30_slots(const SpirvModule& module);

}  // namespace penumbra
