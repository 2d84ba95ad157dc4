#include "jobs.hpp"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace penumbra::cli {

void add_jobs_option(CLI::App* cmd, int& jobs) {
  cmd->add_option("-j,--jobs", jobs,
                  "Threads for the CPU reference, the checks and the pictures, and for Mesa's "
                  "software rasterizers (LP_NUM_THREADS, unless set); default: every core. "
                  "Results are the same for every N")
      ->check(CLI::PositiveNumber);
}

void limit_software_rasterizers(int jobs) {
  if (jobs < 1) return;
  // Not overwritten: a user's own setting wins.
  setenv("LP_NUM_THREADS", std::to_string(jobs).c_str(), 0);
}

void skip_software_jit_optimization() {
  // lavapipe and llvmpipe (Wine's runtimes draw through it too) read it when
  // their first screen is made; a device that is not Mesa's ignores it.
  setenv("GALLIVM_PERF", "nopt", 0);
}

void keep_freed_memory() {
#ifdef __GLIBC__
  // Blocks up to 32 MiB (glibc's largest threshold) come from the heap
  // rather than a mapping of their own, and the heap's free top goes back to
  // the kernel only above 1 GiB: a run keeps its peak memory, which it
  // reaches again within seconds anyway.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

ProgressConsumer stderr_progress(bool quiet) {
  if (quiet) return {};
  return [](const Progress& p) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.1f s", p.seconds);
    std::cerr << "[" << p.done << "/" << p.total << "] " << seconds << " " << p.unit << "\n";
  };
}

}  // namespace penumbra::cli
