// A benchmark's child process, timed from its start to its exit.
#pragma once

#include <filesystem>
#include <map>
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

// An environment for child processes: this one's, with `overrides`.
class Environment {
 public:
  explicit Environment(const std::map<std::string, std::string>& overrides);
  char* const* get() const { return pointers_.data(); }

 private:
  std::vector<std::string> strings_;
  std::vector<char*> pointers_;
};

// A folder of the benchmark's own under the temporary directory, named
// after `prefix` and this process, removed with everything in it.
class ScratchRoot {
 public:
  explicit ScratchRoot(const std::string& prefix);
  ~ScratchRoot();
  ScratchRoot(const ScratchRoot&) = delete;
  ScratchRoot& operator=(const ScratchRoot&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// The seconds run_child() of `argv` took; an error, with its output, when
// it exits other than with 0.
Result<double> seconds_to_succeed(const std::vector<std::string>& argv, char* const* env,
                                  const std::filesystem::path& log);

// The median of `values` (not empty).
double median(std::vector<double> values);

// The whole file, or "" when it cannot be read.
std::string read_text(const std::filesystem::path& path);

}  // namespace penumbra::bench
