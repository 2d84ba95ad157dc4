// Checking a command's output file before the work that fills it.
#pragma once

#include <filesystem>
#include <string>

#include "penumbra/support/result.hpp"

namespace penumbra::cli {

// OK when `path` can be written atomically: its directory exists and may be
// written to (not read-only), and `path` is not a directory. Errors
// (bad_input) name `argument` (when given) and the path.
Status check_output_file(const std::string& path, const std::string& argument);

// Why no file can be made in `dir` (the system's reason: read-only, no
// permission), or empty when one can.
std::string why_unwritable(const std::filesystem::path& dir);

}  // namespace penumbra::cli
