#include "build/pipeline.hpp"

#include "stages/stages.hpp"

namespace penumbra {

Pipeline::Pipeline(std::shared_ptr<const ShaderlibSource> shaderlib,
                   std::optional<std::filesystem::path> write_root,
                   const HlslCompilerOptions& hlsl) {
  stages_.push_back(std::make_unique<PreprocessStage>(shaderlib));
  stages_.push_back(std::make_unique<CompileStage>(std::move(shaderlib)));
  stages_.push_back(std::make_unique<ValidateStage>());
  stages_.push_back(std::make_unique<OptimizeStage>());
  stages_.push_back(std::make_unique<CrossCompileStage>());
  stages_.push_back(std::make_unique<ReflectStage>());
  if (!write_root) return;
  stages_.push_back(std::make_unique<WriteStage>(*write_root));
  if (!hlsl.compiler.empty()) stages_.push_back(std::make_unique<BytecodeStage>(*write_root, hlsl));
}

Status Pipeline::run(ShaderJob& job) const {
  for (const auto& stage : stages_) {
    Status status = stage->process(job);
    if (!status) {
      Error error = status.error();
      error.message = std::string(stage->name()) + ": " + error.message;
      return error;
    }
  }
  return {};
}

}  // namespace penumbra
