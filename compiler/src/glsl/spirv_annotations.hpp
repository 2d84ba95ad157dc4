// Debug annotations glslang cannot produce for Penumbra's SPIR-V 1.0: names
// for the baked constant arrays, and a string naming the variant.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "penumbra/model/model.hpp"

namespace penumbra {

// Adds `OpName %id "BLOCKER_DISK"` / `"PCF_DISK"` (or `"POISSON_DISK"` when
// one constant serves both) for constant arrays whose values are exactly the
// variant's disks, and `"BLUR_WEIGHTS"` for the one that is exactly its blur
// weights. Leaves other constants alone.
// glslang emits no OpName for constants, so SPIRV-Cross would print
// BLOCKER_DISK as `_186`; with the name, every target's text reads like the
// source.
void name_baked_constants(std::vector<std::uint32_t>& spirv, const Variant& variant);

// Puts `prefix` before the OpName of every module-scope name: functions but
// the entry point, global variables but built-ins (gl_*), types and
// constants; names that already start with it stay. Parameters and locals
// keep theirs. The function form's text then declares nothing an engine's
// shader may also declare.
void prefix_global_names(std::vector<std::uint32_t>& spirv, const std::string& prefix);

// Adds `OpString "<text>"` at the head of the debug section: the binary's
// equivalent of the banner comment of text targets (OpModuleProcessed would
// need SPIR-V 1.1). Consumers ignore it; spirv-dis shows it.
void add_banner_string(std::vector<std::uint32_t>& spirv, const std::string& text);

}  // namespace penumbra
