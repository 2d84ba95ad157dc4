#include "glsl/glslang_setup.hpp"

#include <mutex>

#include "penumbra/shaderlib/files.hpp"

namespace penumbra {
namespace {

struct GlslangProcess {
  GlslangProcess() { glslang::InitializeProcess(); }
  ~GlslangProcess() { glslang::FinalizeProcess(); }
};

}  // namespace

void ensure_glslang_initialized() {
  static GlslangProcess process;
}

EShLanguage glslang_stage(ShaderStage stage) {
  return stage == ShaderStage::vertex ? EShLangVertex : EShLangFragment;
}

void configure_environment(glslang::TShader& shader, ShaderStage stage) {
  shader.setEnvInput(glslang::EShSourceGlsl, glslang_stage(stage), glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
}

glslang::TShader::Includer::IncludeResult* ShaderlibIncluder::includeLocal(
    const char* header_name, const char* /*includer_name*/, size_t /*inclusion_depth*/) {
  std::string_view name(header_name);
  if (name == "variant.glsl") {
    return new IncludeResult(header_name, variant_header_.data(), variant_header_.size(), nullptr);
  }
  auto text = shaderlib::file(name);
  if (!text) return nullptr;  // glslang reports the missing include with its location
  return new IncludeResult(header_name, text->data(), text->size(), nullptr);
}

glslang::TShader::Includer::IncludeResult* ShaderlibIncluder::includeSystem(
    const char* header_name, const char* includer_name, size_t inclusion_depth) {
  return includeLocal(header_name, includer_name, inclusion_depth);
}

void ShaderlibIncluder::releaseInclude(IncludeResult* result) {
  delete result;
}

}  // namespace penumbra
