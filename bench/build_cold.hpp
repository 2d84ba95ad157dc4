// penumbra_bench_build --cold-only: a manifest too large to build more than a
// few times (bench/manifests/scale.json) built cold only, side by side: in
// every form, in each --form alone, and by a --baseline executable, each with
// its time, peak memory and index.json size (docs/performance.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "penumbra/support/result.hpp"

namespace penumbra::bench {

struct ColdOptions {
  int jobs = 1;                    // -j of every build
  std::vector<std::string> forms;  // --form F: one more build, in F alone, each
  std::filesystem::path penumbra;  // the executable measured
  std::filesystem::path baseline;  // --baseline EXE: its build of every form too; empty: none
};

// Builds `manifest` as `options` says, with --no-cache and no HLSL
// compiler, and prints one table with the ratios to the first build.
Status bench_cold_builds(const ColdOptions& options, const std::filesystem::path& manifest);

}  // namespace penumbra::bench
