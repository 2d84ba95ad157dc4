// The ordered stages a ShaderJob runs through.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/stage.hpp"

namespace penumbra {

class ShaderCache;

class Pipeline {
 public:
  // preprocess, compile, validate, optimize, cross-compile, reflect, and,
  // when `write_root` is given, write, then bytecode when `hlsl` names a
  // compiler. Shaderlib files come from `shaderlib`. With a write root and a
  // `cache_dir`, finished jobs are cached there and later ones restored.
  Pipeline(std::shared_ptr<const ShaderlibSource> shaderlib,
           std::optional<std::filesystem::path> write_root, const HlslCompilerOptions& hlsl = {},
           const std::filesystem::path& cache_dir = {});
  ~Pipeline();

  // Runs every stage in order; stops at the first error, naming the stage.
  // A job the cache holds runs only preprocess (its key needs the text);
  // then `job.from_cache` is set.
  Status run(ShaderJob& job) const;

  // The time each stage took over every run() so far, in stage order, then
  // the cache's ("cache": keying, restoring, storing) when there is one.
  std::vector<StageTime> profile() const;

 private:
  // One stage's clock, added to by every worker thread.
  struct StageClock {
    std::atomic<std::int64_t> nanoseconds{0};
    std::atomic<std::size_t> runs{0};
  };
  // Runs `work` on the clock of stage `i` (stages_.size(): the cache), and
  // counts one shader there when `counted`.
  template <typename Work>
  auto timed(std::size_t i, Work&& work, bool counted = true) const;

  std::vector<std::unique_ptr<Stage>> stages_;  // preprocess first
  std::optional<std::filesystem::path> write_root_;
  std::unique_ptr<ShaderCache> cache_;
  std::unique_ptr<StageClock[]> clocks_;  // per stage, then the cache
};

}  // namespace penumbra
