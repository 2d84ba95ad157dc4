// Finding vkd3d-compiler, the HLSL compiler and bytecode translator that
// `penumbra build` and `penumbra verify` run.
#pragma once

#include <filesystem>
#include <string>

#include "penumbra/support/result.hpp"

namespace penumbra::cli {

inline constexpr const char* kHlslCompilerHelp =
    "vkd3d-compiler for the Direct3D bytecode (default: $PENUMBRA_HLSL_COMPILER, then "
    "~/.cache/penumbra/vkd3d/bin/vkd3d-compiler)";

// vkd3d-compiler: `flag` (--hlsl-compiler), else $PENUMBRA_HLSL_COMPILER,
// else where scripts/lib/sid-tools.sh installs it ($XDG_CACHE_HOME or
// ~/.cache, then penumbra/vkd3d); empty when none of them has it. A
// flag or variable naming no executable file is a bad_input error.
Result<std::filesystem::path> find_hlsl_compiler(const std::string& flag);

}  // namespace penumbra::cli
