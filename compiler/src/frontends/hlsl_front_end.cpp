#include "frontends/front_end_setup.hpp"
#include "glsl/glslang_setup.hpp"
#include "penumbra/compiler/text_frontend.hpp"
#include "penumbra/model/target_traits.hpp"

namespace penumbra {

FrontEndSetup configure_hlsl_front_end(Target target, ShaderStage stage, glslang::TShader& shader) {
  shader.setEnvInput(glslang::EShSourceHlsl, glslang_stage(stage), glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  shader.setEntryPoint("main");  // SPIRV-Cross's HLSL entry; it wraps vert_main/frag_main
  // Registers become bindings in set 0: b# and t# keep their numbers, s#
  // moves up so that a sampler never shares the binding of its texture (D3D
  // numbers them apart, Vulkan does not). Resources without a register
  // (DX9 samplers, the $Global block) and the entry point's inputs and
  // outputs are assigned in declaration order.
  shader.setShiftBinding(glslang::EResSampler, kHlslSamplerBindingBase);
  shader.setAutoMapBindings(true);
  shader.setAutoMapLocations(true);

  const auto messages =
      static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules | EShMsgReadHlsl);
  const int model = traits(target).shader_model;
  if (model == 3) {
    // sampler2D is one texture+sampler object and loose uniforms with
    // register(c#) land in the $Global block at offset 16 * #, as in D3D9.
    // D3D9 has separate vertex and pixel constant files; the vertex stage's
    // $Global gets its own binding so the two c0 never share a buffer.
    if (stage == ShaderStage::vertex) {
      shader.setShiftBinding(glslang::EResUbo, kDx9VertexConstantsBinding);
    }
    return {"glslang HLSL (DX9-compatible)",
            static_cast<EShMessages>(messages | EShMsgHlslDX9Compatible), true};
  }
  return {"glslang HLSL SM" + std::to_string(model), messages, true};
}

}  // namespace penumbra
