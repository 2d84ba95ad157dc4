// The ordered stages a ShaderJob runs through.
#pragma once

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

 private:
  std::vector<std::unique_ptr<Stage>> stages_;  // preprocess first
  std::optional<std::filesystem::path> write_root_;
  std::unique_ptr<ShaderCache> cache_;
};

}  // namespace penumbra
