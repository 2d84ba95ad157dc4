// The shader cache's location and the build stamps that let an unchanged
// `penumbra build` do nothing (docs/cache.md).
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "penumbra/model/model.hpp"

namespace penumbra::cli {

// --cache-dir, else $PENUMBRA_CACHE_DIR, else $XDG_CACHE_HOME/penumbra or
// ~/.cache/penumbra; empty (no cache) with --no-cache or when there is no
// home directory.
std::filesystem::path cache_directory(const std::string& flag, bool disabled);

// What decides a build's output besides the shaderlib files it reads.
struct BuildInputs {
  std::span<const Variant> variants;    // as selected, with their targets
  std::filesystem::path out;            // OUT
  std::string shaderlib;                // --shaderlib DIR; empty: the embedded copy
  std::filesystem::path hlsl_compiler;  // empty: no bytecode
};

// A finished build's record in the cache directory (builds/<hash of OUT>).
class BuildStamp {
 public:
  // The stamp for OUT, keyed by the inputs and the linked compilers.
  static BuildStamp of(const std::filesystem::path& cache_dir, const BuildInputs& inputs);

  // The shaderlib files (their locations) the recorded build read, when it is
  // still current: same key, OUT/index.json untouched since, and every file
  // it read unchanged. nullopt when the build must run.
  std::optional<std::vector<std::string>> current() const;

  // Records a finished build that read `files` (real files, or none when
  // the shaderlib is the embedded copy, part of the executable). A failure
  // to record costs only the next no-op, so nothing is returned.
  void record(const std::vector<std::string>& files) const;

 private:
  std::filesystem::path stamp_path_;
  std::filesystem::path index_;
  std::string key_;
};

}  // namespace penumbra::cli
