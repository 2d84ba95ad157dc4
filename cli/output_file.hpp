// Checking a command's output file before the work that fills it.
#pragma once

#include <string>

#include "penumbra/support/result.hpp"

namespace penumbra::cli {

// OK when `path` can be written atomically: its directory exists and may be
// written to (not read-only), and `path` is not a directory. Errors
// (bad_input) name `argument` (when given) and the path.
Status check_output_file(const std::string& path, const std::string& argument);

}  // namespace penumbra::cli
