// Names the Poisson-disk constant arrays in a SPIR-V module after their
// source names. glslang emits no OpName for constants, so SPIRV-Cross would
// print BLOCKER_DISK as `_186`; with the name, every target's text reads like
// the source.
#pragma once

#include <cstdint>
#include <vector>

#include "penumbra/compiler/model.hpp"

namespace penumbra {

// Adds `OpName %id "BLOCKER_DISK"` / `"PCF_DISK"` (or `"POISSON_DISK"` when
// one constant serves both) for constant arrays whose values are exactly the
// variant's disks. Leaves other constants alone.
void name_disk_constants(std::vector<std::uint32_t>& spirv, const Variant& variant);

}  // namespace penumbra
