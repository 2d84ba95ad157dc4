// What a pass runs with: SPIR-V stages with their reflection, and the values
// of the ShadowParams uniform block (docs/shader-interface.md).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/compiler/reflection.hpp"

namespace penumbra {

// One stage: its SPIR-V words and the reflection of those words. The runtime
// binds resources, vertex inputs and outputs by `iface`, never by slot.
struct StageCode {
  std::vector<std::uint32_t> spirv;
  ShaderInterface iface;
};

// A vertex + fragment pair: the depth pass, a query pass, or any other pass.
// The SPIR-V may come from Penumbra's shaderlib or from any target's emitted
// text compiled by glslang (docs/runtime.md).
struct PassProgram {
  StageCode vert;
  StageCode frag;
  // The vertex stage flips y for Direct3D: the runtime flips the viewport
  // (negative height, Vulkan 1.1) so row 0 stays first.
  bool d3d_viewport = false;
  // The vertex stage writes OpenGL clip z in [-w, w]: the runtime clips there
  // too (VK_EXT_depth_clip_control).
  bool gl_clip_depth = false;
};

// ShadowParams member name -> its vec4 value, e.g. "light" -> {L, Fw, n, L/Fw}.
// Every member the program's blocks declare must be present (under its
// param_block_key); extra entries are ignored, so one ParamBlock can serve
// every pass and every target.
using ParamBlock = std::map<std::string, std::array<float, 4>>;

// The ParamBlock key a uniform block member reads: the member's name without
// a leading "params." (a struct member of GLSL's global block, e.g.
// "params.light") or "params_" (SPIRV-Cross's HLSL flattening, e.g.
// "params_light"), where `params` is ShadowParams' instance name; any other
// name is its own key ("light", "gl_HalfPixel").
std::string_view param_block_key(std::string_view member_name);

}  // namespace penumbra
