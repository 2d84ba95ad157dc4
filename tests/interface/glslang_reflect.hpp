// glslang's reflection of one emitted stage, parsed as its target's
// language with none of the compiler's settings (no binding shifts, no
// automatic mapping): what glslang reads in the text itself. Used by the
// ESSL and HLSL proofs, and by the GL proof to tell the struct members a
// GLSL 3.30 stage reads.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "penumbra/spirv/reflection.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra::testing {

enum class GlslangSource {
  glsl,      // #version picks the profile: 330, 300 es
  hlsl,      // entry "main"
  hlsl_dx9,  // entry "main", DX9-compatible (sampler2D, register(c#))
};

struct GlslangObject {
  std::string name;      // as glslang reflects it: "ShadowParams.light", "params.light"
  std::string type;      // "vec4", "sampler2D", "sampler2DShadow", "texture2D", "sampler",
                         // "samplerShadow"
  int binding = -1;      // layout(binding = N) or HLSL register number; -1 when none
  int offset = -1;       // bytes in its block; -1 outside a block
  int block = -1;        // index in GlslangReflection::blocks; -1 outside a block
  bool live = false;     // the stage reads it
  std::string semantic;  // inputs and outputs: the HLSL semantic
  int location = -1;     // inputs and outputs: layout(location = N); -1 when none
  int components = 0;    // vector size
};

struct GlslangBlock {
  std::string name;  // "ShadowParams", "$Global"
  int binding = -1;
  int size = 0;  // bytes
};

struct GlslangReflection {
  std::vector<GlslangObject> uniforms;  // every member of a live block, live or not
  std::vector<GlslangBlock> blocks;
  std::vector<GlslangObject> inputs;   // every stage input
  std::vector<GlslangObject> outputs;  // every stage output
};

// The error carries glslang's log.
Result<GlslangReflection> glslang_reflect(std::string_view text, ShaderStage stage,
                                          GlslangSource source);

}  // namespace penumbra::testing
