// Running an external program (no shell) with a time limit, its output captured.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "penumbra/support/result.hpp"

namespace penumbra {

struct ProcessRun {
  int exit_code = -1;      // the program's exit status; -1 when killed or timed out
  bool timed_out = false;  // still running at the time limit: killed, with its children
  std::string output;      // stdout and stderr, interleaved as written
};

// Runs `argv[0]` (a path; PATH is not searched) with `argv`, stdin empty, in
// a process group of its own that is killed when `timeout` passes. Safe to
// call from several threads. The error is for a program that cannot be
// started; a failing or timed-out program is a ProcessRun.
Result<ProcessRun> run_process(const std::vector<std::string>& argv,
                               std::chrono::milliseconds timeout);

}  // namespace penumbra
