#include "build/pipeline.hpp"

#include "cache/shader_cache.hpp"
#include "stages/stages.hpp"
#include "vkd3d/run_vkd3d.hpp"

namespace penumbra {
namespace {

Status run_stage(const Stage& stage, ShaderJob& job) {
  Status status = stage.process(job);
  if (!status) {
    Error error = status.error();
    error.message = std::string(stage.name()) + ": " + error.message;
    return error;
  }
  return {};
}

// The tools a cached file came from: the linked compilers, and the HLSL
// compiler's own version line when the build makes bytecode.
std::string cache_toolchain(const HlslCompilerOptions& hlsl) {
  std::string out = toolchain_id();
  if (hlsl.compiler.empty()) return out;
  auto version = run_vkd3d(hlsl.compiler, {"--version"}, hlsl.timeout);
  out +=
      "; hlsl " + (version && version->exit_code == 0 ? version->output : hlsl.compiler.string());
  return out;
}

}  // namespace

Pipeline::Pipeline(std::shared_ptr<const ShaderlibSource> shaderlib,
                   std::optional<std::filesystem::path> write_root, const HlslCompilerOptions& hlsl,
                   const std::filesystem::path& cache_dir)
    : write_root_(std::move(write_root)) {
  stages_.push_back(std::make_unique<PreprocessStage>(shaderlib));
  stages_.push_back(std::make_unique<CompileStage>(std::move(shaderlib)));
  stages_.push_back(std::make_unique<ValidateStage>());
  stages_.push_back(std::make_unique<OptimizeStage>());
  stages_.push_back(std::make_unique<CrossCompileStage>());
  stages_.push_back(std::make_unique<ReflectStage>());
  stages_.push_back(std::make_unique<ExtractFunctionStage>());
  if (!write_root_) return;
  stages_.push_back(std::make_unique<WriteStage>(*write_root_));
  if (!hlsl.compiler.empty()) {
    stages_.push_back(std::make_unique<BytecodeStage>(*write_root_, hlsl));
  }
  if (!cache_dir.empty()) cache_ = std::make_unique<ShaderCache>(cache_dir, cache_toolchain(hlsl));
}

Pipeline::~Pipeline() = default;

Status Pipeline::run(ShaderJob& job) const {
  PENUMBRA_TRY(run_stage(*stages_.front(), job));
  std::string key;
  if (cache_) {
    key = cache_->key(job);
    if (cache_->restore(key, job, *write_root_)) {
      job.from_cache = true;
      return {};
    }
  }
  for (std::size_t i = 1; i < stages_.size(); ++i) PENUMBRA_TRY(run_stage(*stages_[i], job));
  if (cache_) cache_->store(key, job, *write_root_);
  return {};
}

}  // namespace penumbra
