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

class ModuleMemo;
class ShaderCache;

class Pipeline {
 public:
  // preprocess; the module stages compile, validate and optimize, whose
  // module jobs with the same module_key() share; then the target's own:
  // banner, cross-compile, reflect, extract-function, and, when
  // `write_root` is given, write, then bytecode when `hlsl` names a
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
  // "shared-module" (keying and finding modules; its runs are the jobs that
  // took another's), then the cache's ("cache": keying, restoring, storing)
  // when there is one.
  std::vector<StageTime> profile() const;

 private:
  // One stage's clock, added to by every worker thread.
  struct StageClock {
    std::atomic<std::int64_t> nanoseconds{0};
    std::atomic<std::size_t> runs{0};
  };
  // Runs `work` on the clock of stage `i` (stages_.size(): the cache; one
  // more: shared modules), and counts one shader there when `counted`.
  template <typename Work>
  auto timed(std::size_t i, Work&& work, bool counted = true) const;
  // Runs stages_[first, last) on `job`, each on its clock.
  Status run_stages(std::size_t first, std::size_t last, ShaderJob& job) const;
  // The module stages, or the module of an earlier job with job's key.
  Status make_module(ShaderJob& job) const;

  // preprocess, the kModuleStages module stages, then the target's.
  std::vector<std::unique_ptr<Stage>> stages_;
  std::optional<std::filesystem::path> write_root_;
  std::unique_ptr<ShaderCache> cache_;
  std::unique_ptr<ModuleMemo> modules_;
  std::unique_ptr<StageClock[]> clocks_;  // per stage, then the cache's, then shared-module's
};

}  // namespace penumbra
