// Running vkd3d-compiler: the build's HLSL compiler and disassembler, and
// verify's bytecode translator.
#pragma once

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "penumbra/support/process.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

// Runs `compiler` with `arguments`. The error (io, at the compiler's path)
// is for a compiler that cannot be started; its failures are a ProcessRun.
Result<ProcessRun> run_vkd3d(const std::filesystem::path& compiler,
                             std::vector<std::string> arguments, std::chrono::milliseconds timeout);

}  // namespace penumbra
