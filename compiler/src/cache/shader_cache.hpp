// The content-addressed shader cache (docs/cache.md): a finished job's
// output files, reflection and warnings, keyed by everything that decides
// them, so that a later build skips compiling a shader it has made before.
#pragma once

#include <filesystem>
#include <string>

#include "penumbra/compiler/stage.hpp"

namespace penumbra {

class ShaderCache {
 public:
  // `dir` need not exist yet. `toolchain` names every tool whose output a
  // cached file is (toolchain_id(), plus the HLSL compiler's version when
  // the build makes bytecode).
  ShaderCache(std::filesystem::path dir, std::string toolchain);

  // The key of a preprocessed job: its preprocessed source, what it is
  // (variant, target, pass, stage, output path) and the toolchain.
  std::string key(const ShaderJob& job) const;

  // On a hit, writes the job's files under `root` and fills in its
  // reflection, bytecode record and warnings; false on a miss. An entry that
  // cannot be read or is damaged is a miss.
  bool restore(const std::string& key, ShaderJob& job, const std::filesystem::path& root) const;

  // Stores a finished job whose files are under `root`. Entries are written
  // atomically; a failure to store is not an error for the build (it only
  // costs a later rebuild), so nothing is returned.
  void store(const std::string& key, const ShaderJob& job, const std::filesystem::path& root) const;

 private:
  std::filesystem::path entry_path(const std::string& key) const;

  std::filesystem::path dir_;
  std::string toolchain_;
};

}  // namespace penumbra
