// `-j/--jobs` and `-q/--quiet` of verify and report: how many cores they
// use, how Mesa's software rasterizers compile for them, and the progress
// they print.
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

// Makes Mesa's software rasterizers compile shaders without LLVM's
// optimizations (GALLIVM_PERF=nopt), unless the user set GALLIVM_PERF: the
// same results from shaders compiled in a fraction of the time, but slower
// draws (docs/performance.md, "The shader JIT unoptimized"). For verify, not
// for report, whose GPU costs time the draws. Before the first device.
void skip_software_jit_optimization();

// Has the allocator keep freed memory for the next allocation instead of
// handing every large block back to the kernel: verify and report allocate
// and free images of megabytes per check, and each block handed back costs
// its page faults again when the next image takes it (docs/performance.md,
// "Nothing made that no check reads"). glibc only; elsewhere nothing.
void keep_freed_memory();

// Prints "[done/total] elapsed unit" lines to stderr; none when `quiet`.
ProgressConsumer stderr_progress(bool quiet);

}  // namespace penumbra::cli
