#include <glslang/Public/ResourceLimits.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include "frontends/front_end_setup.hpp"
#include "frontends/shims.hpp"
#include "glsl/glslang_setup.hpp"
#include "penumbra/compiler/targets.hpp"
#include "penumbra/compiler/text_frontend.hpp"
#include "spirv/validation.hpp"

namespace penumbra {
namespace {

// "glslang HLSL SM4 rejected the hlsl_dx10 text:\n<log>", at the file.
Error rejected(Target target, std::string_view name, std::string_view front_end,
               std::string_view log) {
  return make_error(Error::Kind::compile, std::string(name),
                    std::string(front_end) + " rejected the " + std::string(to_string(target)) +
                        " text:\n" + std::string(log));
}

}  // namespace

Result<FrontEndResult> compile_target_text(Target target, ShaderStage stage, std::string_view text,
                                           std::string_view name) {
  if (!traits(target).is_text) {
    return make_error(Error::Kind::bad_input, std::string(name),
                      "target spirv has no text to compile; it is the SPIR-V itself");
  }
  auto shimmed = apply_shims(target, text);
  if (!shimmed) return rejected(target, name, "a front-end shim", shimmed.error().message);

  ensure_glslang_initialized();
  const EShLanguage language = glslang_stage(stage);
  glslang::TShader shader(language);
  const std::string file(name);
  const char* source = shimmed->text.c_str();
  const char* file_name = file.c_str();
  const int length = static_cast<int>(shimmed->text.size());
  shader.setStringsWithLengthsAndNames(&source, &length, &file_name, 1);
  const FrontEndSetup setup = traits(target).is_hlsl
                                  ? configure_hlsl_front_end(target, stage, shader)
                                  : configure_glsl_front_end(target, stage, shader);

  // Every emitted text names its #version; 100 only stands in for none.
  if (!shader.parse(GetDefaultResources(), 100, false, setup.messages)) {
    return rejected(target, name, setup.description, shader.getInfoLog());
  }
  // mapIO assigns the auto-mapped bindings and locations (the stage alone:
  // it sees no other stage, so varyings are placed in declaration order).
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(setup.messages) || !program.mapIO()) {
    return rejected(target, name, setup.description, program.getInfoLog());
  }

  FrontEndResult result{{}, setup.description, std::move(shimmed->shims)};
  glslang::SpvOptions options;
  options.disableOptimizer = !setup.legalize;
  spv::SpvBuildLogger logger;
  glslang::GlslangToSpv(*program.getIntermediate(language), result.spirv, &logger, &options);
  if (result.spirv.empty()) {
    return rejected(target, name, setup.description, logger.getAllMessages());
  }
  if (auto valid = validate_vulkan_spirv(result.spirv); !valid) {
    return rejected(target, name, setup.description, valid.error().message);
  }
  return result;
}

}  // namespace penumbra
