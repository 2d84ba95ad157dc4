// The options of verify and report that choose execution paths, read from
// the paths' table (penumbra/verify/paths.hpp): --path, and each path's
// skip flag (--no-gl, --no-wine).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "penumbra/support/result.hpp"

namespace penumbra::cli {

// Adds every skip flag of the paths' table to `cmd`: each given one adds
// its paths to `skipped` (VerifyOptions::skipped).
void add_skip_flags(CLI::App* cmd, std::vector<std::string>& skipped);

// OK when every --path value names a path; otherwise bad input naming it
// and the allowed ones.
Status check_path_names(const std::vector<std::string>& paths);

}  // namespace penumbra::cli
