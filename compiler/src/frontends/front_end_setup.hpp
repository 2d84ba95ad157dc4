// How each text target is handed to glslang: the source language, the parse
// messages and the TShader options that map its bindings and locations for
// Vulkan. One function per front end; the options are listed per target in
// docs/frontends.md.
#pragma once

#include <glslang/Public/ShaderLang.h>

#include <string>

#include "penumbra/model/model.hpp"
#include "penumbra/spirv/reflection.hpp"

namespace penumbra {

struct FrontEndSetup {
  std::string description;  // FrontEndResult::front_end
  EShMessages messages = EShMsgDefault;
  bool legalize = false;  // run glslang's HLSL legalization (spirv-opt) after translation
};

// glsl450, glsl330 and essl300.
FrontEndSetup configure_glsl_front_end(Target target, ShaderStage stage, glslang::TShader& shader);

// The HLSL targets, by shader model.
FrontEndSetup configure_hlsl_front_end(Target target, ShaderStage stage, glslang::TShader& shader);

}  // namespace penumbra
