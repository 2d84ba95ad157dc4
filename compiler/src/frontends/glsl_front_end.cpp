#include <string>

#include "frontends/front_end_setup.hpp"
#include "glsl/glslang_setup.hpp"
#include "penumbra/compiler/text_frontend.hpp"

namespace penumbra {

FrontEndSetup configure_glsl_front_end(Target target, ShaderStage stage, glslang::TShader& shader) {
  // The same Vulkan 1.0 / SPIR-V 1.0 environment the library's own SPIR-V
  // is compiled in.
  configure_environment(shader, stage);
  // Emitted GLSL 3.30 and ESSL 3.00 have no binding qualifiers and their
  // varyings no locations: both are assigned here, in declaration order,
  // where the text gives none. Explicit ones (glsl450) are kept.
  shader.setAutoMapBindings(true);
  shader.setAutoMapLocations(true);

  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  switch (target) {
    case Target::glsl330: {
      // GLSL 3.30 sets `uniform ShadowParams params;` and samplers by name;
      // Vulkan has no loose uniforms. The relaxed rules gather them into one
      // uniform block (set 0, binding 0) instead of rejecting them.
      shader.setEnvInputVulkanRulesRelaxed();
      shader.setGlobalUniformBlockName(std::string(kLooseUniformBlockName).c_str());  // copied
      shader.setGlobalUniformSet(0);
      shader.setGlobalUniformBinding(0);
      return {"glslang GLSL 330 (Vulkan relaxed rules)", messages};
    }
    case Target::essl300:
      return {"glslang ESSL 310", messages};
    default:
      return {"glslang GLSL 450", messages};
  }
}

}  // namespace penumbra
