// The ordered stages a ShaderJob runs through.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/stage.hpp"

namespace penumbra {

class Pipeline {
 public:
  // preprocess, compile, validate, optimize, cross-compile, reflect, and,
  // when `write_root` is given, write, then bytecode when `hlsl` names a
  // compiler. Shaderlib files come from `shaderlib`.
  Pipeline(std::shared_ptr<const ShaderlibSource> shaderlib,
           std::optional<std::filesystem::path> write_root, const HlslCompilerOptions& hlsl = {});

  // Runs every stage in order; stops at the first error, naming the stage.
  Status run(ShaderJob& job) const;

 private:
  std::vector<std::unique_ptr<Stage>> stages_;
};

}  // namespace penumbra
