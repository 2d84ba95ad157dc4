#include <glslang/Public/ResourceLimits.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include "glsl/glslang_setup.hpp"
#include "glsl/spirv_annotations.hpp"
#include "stages/stages.hpp"

namespace penumbra {

Status CompileStage::process(ShaderJob& job) const {
  ensure_glslang_initialized();
  const EShLanguage language = glslang_stage(job.stage);
  glslang::TShader shader(language);
  const char* text = job.preprocessed.c_str();
  const char* name = job.source_path.c_str();
  const int length = static_cast<int>(job.preprocessed.size());
  shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
  configure_environment(shader, job.stage);

  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  if (!shader.parse(GetDefaultResources(), 450, false, messages)) {
    return glslang_error(*shaderlib_, job.describe(), "glslang failed: ", shader.getInfoLog(),
                         job.source_path);
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    return make_error(Error::Kind::compile, job.describe(),
                      std::string("glslang link failed:\n") + program.getInfoLog());
  }

  glslang::SpvOptions options;
  options.disableOptimizer = true;  // optimization is its own stage
  spv::SpvBuildLogger logger;
  job.spirv.clear();
  glslang::GlslangToSpv(*program.getIntermediate(language), job.spirv, &logger, &options);
  if (job.spirv.empty()) {
    return make_error(Error::Kind::compile, job.describe(),
                      "SPIR-V generation failed:\n" + logger.getAllMessages());
  }
  if (job.variant) name_baked_constants(job.spirv, *job.variant);
  if (job.form == ShaderForm::function)
    prefix_global_names(job.spirv, std::string(kFunctionPrefix));
  return {};
}

}  // namespace penumbra
