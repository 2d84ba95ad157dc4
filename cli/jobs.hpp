// `-j/--jobs` and `-q/--quiet` of verify and report: how many cores they
// use, and the progress they print.
#pragma once

#include <CLI/CLI.hpp>

#include "penumbra/verify/progress.hpp"

namespace penumbra::cli {

// Adds -j/--jobs N (at least 1; default 0, every core) to `cmd`.
void add_jobs_option(CLI::App* cmd, int& jobs);

// Makes Mesa's software rasterizers (lavapipe, llvmpipe: LP_NUM_THREADS) use
// `jobs` threads too, unless the user set that, so that --jobs bounds the
// cores the whole run uses. Before the first device is created.
void limit_software_rasterizers(int jobs);

// Prints "[done/total] elapsed unit" lines to stderr; none when `quiet`.
ProgressConsumer stderr_progress(bool quiet);

}  // namespace penumbra::cli
