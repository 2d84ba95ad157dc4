// penumbra_bench_build's runs of the `penumbra` executable: one build as a
// child process, what its summary line says, its time and peak memory, and
// the table rows the benchmark prints.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_child.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::bench {

// `penumbra build`'s summary line: "built V variants (F shader files, B
// bytecode files, C shaders from the cache) into OUT".
struct BuildCounts {
  std::size_t variants = 0;
  std::size_t files = 0;
  std::size_t bytecode = 0;
  std::size_t cached = 0;
  bool up_to_date = false;  // "OUT is up to date": nothing built
};

BuildCounts parse_summary(const std::string& output);

// One run of `penumbra`, or of several at once (a split build).
struct Measured {
  double seconds = 0.0;
  long peak_rss_kb = 0;
  BuildCounts counts;
};

// Runs one `penumbra` executable under `root`, with an environment that
// finds no HLSL compiler unless given one: PENUMBRA_HLSL_COMPILER empty and
// a HOME of its own, without ~/.cache/penumbra/vkd3d. Every build names its
// cache, or --no-cache.
class BuildRunner {
 public:
  BuildRunner(std::filesystem::path root, std::filesystem::path penumbra);

  const std::filesystem::path& root() const { return root_; }

  // `penumbra ARGS`, which must succeed; `log` names its output file.
  Result<Measured> penumbra(std::vector<std::string> args, const std::string& log) const;

  // `penumbra build MANIFEST -o OUT -j JOBS EXTRA...`.
  Result<Measured> build(const std::filesystem::path& manifest, const std::filesystem::path& out,
                         int jobs, const std::vector<std::string>& extra) const;

 private:
  std::filesystem::path root_;
  std::filesystem::path penumbra_;  // the executable run
  Environment env_;
};

double mib(long kb);

// "| what | wall s | shaders/s | peak RSS MiB | note |".
void print_row(const std::string& what, double seconds, std::size_t shaders, long rss_kb,
               const std::string& note = "");

}  // namespace penumbra::bench
