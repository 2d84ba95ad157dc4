// What a pass runs with: SPIR-V stages, the reflection record an engine
// binds by, and the values of the ShadowParams uniform block
// (docs/shader-interface.md, docs/runtime.md).
#pragma once

#include <cstdint>
#include <vector>

#include "penumbra/model/target_reflection.hpp"
#include "penumbra/spirv/reflection.hpp"
#include "penumbra/support/param_block.hpp"  // ParamBlock, param_block_key

namespace penumbra {

// One stage as the device runs it: its SPIR-V words and their reflection,
// which plays the driver's view of the module (the descriptors it declares).
struct StageCode {
  std::vector<std::uint32_t> spirv;
  ShaderInterface iface;
};

// A vertex + fragment pair: the depth pass, a query pass, or any other pass.
// The SPIR-V may come from Penumbra's shaderlib, from any target's emitted
// text compiled by glslang, or from a Direct3D target's bytecode translated
// by vkd3d-compiler (docs/runtime.md). The runtime creates and binds
// every resource from `reflection`, read in `target`'s terms.
struct PassProgram {
  StageCode vert;
  StageCode frag;
  Target target = Target::spirv;  // whose text the stages were compiled from
  PassReflection reflection;      // index.json's reflection.<pass>.<target>
  // The vertex stage flips y for Direct3D: the runtime flips the viewport
  // (negative height, Vulkan 1.1) so row 0 stays first.
  bool d3d_viewport = false;
  // The vertex stage writes OpenGL clip z in [-w, w]: the runtime clips there
  // too (VK_EXT_depth_clip_control).
  bool gl_clip_depth = false;
  // The stages are vkd3d-compiler's translation of `target`'s Direct3D
  // bytecode: resources named by register, bound by the record's registers.
  bool d3d_bytecode = false;
};

}  // namespace penumbra
