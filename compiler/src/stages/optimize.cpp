#include <spirv-tools/optimizer.hpp>

#include "stages/stages.hpp"

namespace penumbra {

Status OptimizeStage::process(ShaderJob& job) const {
  spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_0);
  std::string messages;
  optimizer.SetMessageConsumer(
      [&messages](spv_message_level_t, const char*, const spv_position_t&, const char* message) {
        messages += std::string(message) + "\n";
      });
  // No inlining and no SSA rewriting: those replace named locals and
  // functions with numbered temporaries in the cross-compiled text. These
  // passes only fold and remove what is provably dead.
  optimizer.RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass())
      .RegisterPass(spvtools::CreateDeadBranchElimPass())
      .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass())
      .RegisterPass(spvtools::CreateAggressiveDCEPass(/*preserve_interface=*/true))
      .RegisterPass(spvtools::CreateEliminateDeadConstantPass())
      .RegisterPass(spvtools::CreateCFGCleanupPass());

  std::vector<std::uint32_t> optimized;
  // ValidateStage has just validated this module, with the same rules: a
  // second validation here took a sixth of a build (docs/performance.md).
  spvtools::OptimizerOptions options;
  options.set_run_validator(false);
  if (!optimizer.Run(job.spirv.data(), job.spirv.size(), &optimized, options)) {
    return make_error(Error::Kind::compile, job.describe(), "spirv-opt failed:\n" + messages);
  }
  job.spirv = std::move(optimized);
  return {};
}

}  // namespace penumbra
