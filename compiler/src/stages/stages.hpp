// The pipeline's stages, in order. Each lives in its own source file.
#pragma once

#include <filesystem>
#include <memory>

#include "glsl/preprocess_memo.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/shaderlib_source.hpp"
#include "penumbra/compiler/stage.hpp"

namespace penumbra {

// Resolves includes and defines (variant.glsl) with glslang's preprocessor,
// reading shaderlib files from `shaderlib` and recording them in job.inputs.
// A job whose variant.glsl differs from a recent one's only in macros none
// of its files mention takes that one's text (PreprocessMemo).
class PreprocessStage final : public Stage {
 public:
  explicit PreprocessStage(std::shared_ptr<const ShaderlibSource> shaderlib)
      : shaderlib_(std::move(shaderlib)), memo_(kRecentTexts, *shaderlib_) {}
  std::string_view name() const override { return "preprocess"; }
  Status process(ShaderJob& job) const override;

 private:
  // A pass's targets follow each other in a build's plan: a short memory
  // finds them.
  static constexpr std::size_t kRecentTexts = 64;
  std::shared_ptr<const ShaderlibSource> shaderlib_;
  mutable PreprocessMemo memo_;
};

// Compiles the preprocessed GLSL to SPIR-V 1.0 with glslang, in process. Its
// errors are located in the shaderlib file and line they are about. The
// module it makes depends on what module_key() names, not on the target.
class CompileStage final : public Stage {
 public:
  explicit CompileStage(std::shared_ptr<const ShaderlibSource> shaderlib)
      : shaderlib_(std::move(shaderlib)) {}
  std::string_view name() const override { return "compile"; }
  Status process(ShaderJob& job) const override;

 private:
  std::shared_ptr<const ShaderlibSource> shaderlib_;
};

// Checks the SPIR-V with spirv-val's rules for Vulkan 1.0.
class ValidateStage final : public Stage {
 public:
  std::string_view name() const override { return "validate"; }
  Status process(ShaderJob& job) const override;
};

// Runs spirv-opt passes that remove dead code but keep names and functions,
// so that cross-compiled text stays readable.
class OptimizeStage final : public Stage {
 public:
  std::string_view name() const override { return "optimize"; }
  Status process(ShaderJob& job) const override;
};

// Reads the module's interface with SPIRV-Cross (what it binds and passes),
// which no target changes: the last of the module stages, so the targets
// that share a module share it.
class InterfaceStage final : public Stage {
 public:
  std::string_view name() const override { return "interface"; }
  Status process(ShaderJob& job) const override;
};

// Heads the module with the job's banner, an OpString naming variant, target,
// pass and stage: the first of the stages that are the target's own.
class BannerStage final : public Stage {
 public:
  std::string_view name() const override { return "banner"; }
  Status process(ShaderJob& job) const override;
};

// Checks the target's rules, then emits GLSL or HLSL text with SPIRV-Cross.
class CrossCompileStage final : public Stage {
 public:
  std::string_view name() const override { return "cross-compile"; }
  Status process(ShaderJob& job) const override;
};

// The target's reflection of the module's interface: names, registers,
// formats and samplers as the target's API binds them.
class ReflectStage final : public Stage {
 public:
  std::string_view name() const override { return "reflect"; }
  Status process(ShaderJob& job) const override;
};

// The function form's text: the cross-compiled module less its harness (the
// entry point, its input and output, #version and default precisions); its
// #extension lines go to the reflection, with penumbra_visibility()'s
// declaration. Jobs of other forms pass through.
class ExtractFunctionStage final : public Stage {
 public:
  std::string_view name() const override { return "extract-function"; }
  Status process(ShaderJob& job) const override;
};

// Writes the target's file, headed by a comment naming variant and keys,
// under a root directory (the build's staging directory).
class WriteStage final : public Stage {
 public:
  explicit WriteStage(std::filesystem::path root) : root_(std::move(root)) {}
  std::string_view name() const override { return "write"; }
  Status process(ShaderJob& job) const override;

 private:
  std::filesystem::path root_;
};

// Compiles the written HLSL file (the HLSL targets) to Direct3D bytecode
// beside it with an external HLSL compiler, within the options' time limit.
// Its errors fail the job with the compiler's message and the HLSL line;
// its warnings become the job's diagnostics. Other targets pass through.
class BytecodeStage final : public Stage {
 public:
  BytecodeStage(std::filesystem::path root, HlslCompilerOptions options);
  std::string_view name() const override { return "bytecode"; }
  Status process(ShaderJob& job) const override;

 private:
  // Shader Model 3: the bytecode's instruction slots, and a warning past 512.
  Status count_slots(ShaderJob& job, const std::filesystem::path& bytecode) const;

  std::filesystem::path root_;
  HlslCompilerOptions options_;
};

}  // namespace penumbra
