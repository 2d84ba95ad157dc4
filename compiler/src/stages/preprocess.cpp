#include <glslang/Public/ResourceLimits.h>

#include "glsl/glslang_setup.hpp"
#include "glsl/variant_header.hpp"
#include "penumbra/model/map_layout.hpp"
#include "penumbra/model/model.hpp"
#include "stages/stages.hpp"

namespace penumbra {

Status PreprocessStage::process(ShaderJob& job) const {
  // The manifest refuses such a variant; this refuses it compiled directly.
  if (job.variant) {
    const std::string why = inexact_walk(*job.variant, job.target);
    if (!why.empty()) {
      return make_error(Error::Kind::bad_input, job.describe(),
                        why + "; build it for the other targets, or with a smaller kernel");
    }
    const std::string layout = layout_unsupported(map_layout(job.variant->keys), job.target);
    if (!layout.empty()) {
      return make_error(Error::Kind::bad_input, job.describe(),
                        layout + "; build it for the other targets");
    }
  }
  const std::string header = variant_header(job.variant, job.target, job.map_encoding);
  if (std::optional<Preprocessed> made = memo_.find(job.stage, job.source_path, header)) {
    job.preprocessed = std::move(made->text);
    job.inputs = std::move(made->inputs);
    return {};
  }
  auto source = shaderlib_->read(job.source_path);
  if (!source) {
    return make_error(Error::Kind::bad_input, job.describe(),
                      "shaderlib has no file " + shaderlib_->location(job.source_path));
  }
  job.inputs = {job.source_path};
  ensure_glslang_initialized();
  glslang::TShader shader(glslang_stage(job.stage));
  const char* text = source->data();
  const int length = static_cast<int>(source->size());
  const char* name = job.source_path.c_str();
  shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
  configure_environment(shader, job.stage);

  ShaderlibIncluder includer(*shaderlib_, header, job.inputs);
  std::string output;
  if (!shader.preprocess(GetDefaultResources(), 450, ENoProfile, false, false, EShMsgDefault,
                         &output, includer)) {
    return glslang_error(*shaderlib_, job.describe(), "preprocessing failed: ", shader.getInfoLog(),
                         job.source_path);
  }
  job.preprocessed = std::move(output);
  memo_.add(job.stage, job.source_path, header, {job.preprocessed, job.inputs});
  return {};
}

}  // namespace penumbra
