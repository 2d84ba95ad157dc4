// A benchmark's child process, timed from its start to its exit.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "penumbra/support/result.hpp"

namespace penumbra::bench {

// One finished child process.
struct ChildRun {
  int exit_code = -1;  // -1: ended by a signal
  double seconds = 0.0;
  long peak_rss_kb = 0;  // the child's own ru_maxrss
  std::string output;    // stdout and stderr
};

// Runs argv[0] (a path) with `env`, its output into `log`, read back after.
// wait4 blocks until it exits and gives its peak RSS; no polling, so the
// benchmark adds no latency of its own to each process. The time ends when
// the child does, not when the last holder of its output closes it (a
// Wine helper process may keep it open for seconds after).
Result<ChildRun> run_child(const std::vector<std::string>& argv, char* const* env,
                           const std::filesystem::path& log);

// The whole file, or "" when it cannot be read.
std::string read_text(const std::filesystem::path& path);

}  // namespace penumbra::bench
