// Shared glslang setup: process initialization, the include resolver over the
// embedded shader library, and the environment every shader is parsed in.
#pragma once

#include <glslang/Public/ShaderLang.h>

#include <string>

#include "penumbra/compiler/reflection.hpp"

namespace penumbra {

// Initializes glslang once per process (thread-safe).
void ensure_glslang_initialized();

EShLanguage glslang_stage(ShaderStage stage);

// Vulkan 1.0 client, SPIR-V 1.0 target, GLSL 4.50 source.
void configure_environment(glslang::TShader& shader, ShaderStage stage);

// Resolves `#include "x"` from the embedded shaderlib; "variant.glsl" is the
// generated header given at construction.
class ShaderlibIncluder : public glslang::TShader::Includer {
 public:
  explicit ShaderlibIncluder(std::string variant_header)
      : variant_header_(std::move(variant_header)) {}
  IncludeResult* includeLocal(const char* header_name, const char* includer_name,
                              size_t inclusion_depth) override;
  IncludeResult* includeSystem(const char* header_name, const char* includer_name,
                               size_t inclusion_depth) override;
  void releaseInclude(IncludeResult* result) override;

 private:
  std::string variant_header_;
};

}  // namespace penumbra
