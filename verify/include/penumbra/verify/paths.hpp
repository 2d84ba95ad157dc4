// The execution paths `penumbra verify` and the report run each target on:
// one row each in verify/src/paths.cpp (its name, what it needs, the CLI
// flag that skips it, and the backend it makes), in report order. A new
// path is a row there and a backend file.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace penumbra {

struct ExecutionPath {
  std::string_view name;       // verify.json's `backend`, and --path's value
  std::string_view needs;      // what it needs beyond the Vulkan device, in words
  std::string_view skip_flag;  // the CLI flag that reports it not executed; "" for none
};

// Every path, in report order.
std::vector<ExecutionPath> execution_paths();

// "vulkan, bytecode, gl, d3d9, d3d10, d3d11": the names, as errors list them.
std::string path_names();
bool is_path_name(std::string_view name);

// The paths `flag` skips: "--no-gl" gl, "--no-wine" d3d9, d3d10 and d3d11.
std::vector<std::string> paths_skipped_by(std::string_view flag);

}  // namespace penumbra
