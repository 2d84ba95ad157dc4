// The runtime tests' programs in the shapes of the emitted text targets:
// SPIR-V that glslang's HLSL and GLSL front ends compiled from shaders/ at
// build time, reflected by reflect() as a library's programs are.
#pragma once

#include <string>
#include <string_view>

#include "penumbra/runtime/program.hpp"

namespace penumbra::test {

enum class TextShape {
  hlsl_dx10,        // cbuffer ShadowParams; Texture2D + sampler sharing one binding
  hlsl_dx10_split,  // the same, samplers on bindings of their own (--ssb 8)
  hlsl_dx9,         // $Global constants and gl_HalfPixel; sampler2D; compares in the shader
  glsl330,          // uniform ShadowParams params in gl_DefaultUniformBlock; loose samplers
};

inline constexpr TextShape kTextShapes[] = {TextShape::hlsl_dx10, TextShape::hlsl_dx10_split,
                                            TextShape::hlsl_dx9, TextShape::glsl330};

std::string_view to_string(TextShape shape);

// shaders/<name>.spv with its reflect() record; fails the test if either fails.
StageCode reflected_stage(const std::string& name);

// The depth pass (d3d_viewport set for HLSL).
PassProgram text_depth_program(TextShape shape);

// The query pass: one bilinear comparison at the receiver, as compare.frag
// (Direct3D 9: four point reads, weighted in the shader).
PassProgram text_compare_program(TextShape shape);

}  // namespace penumbra::test
