// What a pass runs with: SPIR-V stages with their reflection, and the values
// of the ShadowParams uniform block (docs/shader-interface.md).
#pragma once

#include <cstdint>
#include <vector>

#include "penumbra/compiler/reflection.hpp"
#include "penumbra/support/param_block.hpp"  // ParamBlock, param_block_key

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

}  // namespace penumbra
