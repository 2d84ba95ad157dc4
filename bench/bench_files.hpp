// Where a benchmark finds what it needs by default, so that it runs wherever
// its executable is: in the build tree, installed, or packed for another
// machine (scripts/pack-portable.sh), never from the source tree's path.
#pragma once

#include <filesystem>
#include <string_view>

#include "penumbra/support/result.hpp"

namespace penumbra::bench {

// A manifest shipped with Penumbra (`name`: "default.json"), from the first
// of: EXE/../share/penumbra/permutations (installed, and the build tree's
// copy), then ./permutations (a packed build run from a checkout).
Result<std::filesystem::path> default_manifest(std::string_view name);

// The `penumbra` executable: beside this one (installed, packed), then one
// folder up (the build tree's bench/).
Result<std::filesystem::path> penumbra_executable();

}  // namespace penumbra::bench
