// Shared glslang setup: process initialization, the include resolver over the
// shader library, the environment every shader is parsed in, and glslang's
// messages mapped back to the shaderlib files they are about.
#pragma once

#include <glslang/Public/ShaderLang.h>

#include <string>
#include <string_view>
#include <vector>

#include "penumbra/compiler/shaderlib_source.hpp"
#include "penumbra/spirv/reflection.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

// Initializes glslang once per process (thread-safe).
void ensure_glslang_initialized();

EShLanguage glslang_stage(ShaderStage stage);

// Vulkan 1.0 client, SPIR-V 1.0 target, GLSL 4.50 source.
void configure_environment(glslang::TShader& shader, ShaderStage stage);

// Resolves `#include "x"` from a shader library source, appending each file
// it reads to `read`; "variant.glsl" is the generated header given at
// construction. glslang names every included text by its shaderlib path
// (its #line directives too), so the output does not depend on the source.
class ShaderlibIncluder : public glslang::TShader::Includer {
 public:
  ShaderlibIncluder(const ShaderlibSource& source, std::string variant_header,
                    std::vector<std::string>& read)
      : source_(source), variant_header_(std::move(variant_header)), read_(read) {}
  IncludeResult* includeLocal(const char* header_name, const char* includer_name,
                              size_t inclusion_depth) override;
  IncludeResult* includeSystem(const char* header_name, const char* includer_name,
                               size_t inclusion_depth) override;
  void releaseInclude(IncludeResult* result) override;

 private:
  const ShaderlibSource& source_;
  std::string variant_header_;
  std::vector<std::string>& read_;
};

// A failed preprocess or parse as an Error located in the shaderlib file of
// glslang's first error: `where` is "LOCATION:LINE[:COL]: <context>"
// (LOCATION from `source`; COL where the token glslang names is on the
// line), `message` is `heading` and glslang's message, then its other
// messages GCC-style ("LOCATION:LINE[:COL]: error: ..."); a source-string
// number names `pass`, the shaderlib path of the job's source. Without a
// place in the log, the whole log under `heading`, located at `context`.
Error glslang_error(const ShaderlibSource& source, const std::string& context,
                    std::string_view heading, std::string_view log, std::string_view pass);

}  // namespace penumbra
