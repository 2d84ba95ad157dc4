// What distinguishes one target from another, in one place: the defines the
// shader source sees and the file names of its output.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "penumbra/compiler/reflection.hpp"
#include "penumbra/model/model.hpp"

namespace penumbra {

struct TargetTraits {
  bool comparison_sampler = true;  // has sampler2DShadow / SampleCmp; false for hlsl_dx9
  bool is_hlsl = false;            // HLSL text (y flipped for D3D's viewport)
  bool is_text = true;             // false for spirv (binary output)
  int shader_model = 0;            // HLSL: the Direct3D bytecode's shader model (3 or 4); else 0
  // Reads Poisson disks from the pcf_disk/blocker_disk textures rather than
  // constant arrays (hlsl_dx9: Shader Model 3 indexes those by compare chains).
  bool disk_textures = false;
  // Keeps the per-sample loops rolled (HLSL [loop]): Direct3D compilers
  // unroll at compile time, which takes minutes at the largest sample
  // counts and overflows ps_3_0's 512 instruction slots.
  bool rolled_sample_loops = false;
};

TargetTraits traits(Target target);

// `#define` lines for the target, included into every shader via variant.glsl.
std::string target_defines(Target target);

// The Direct3D bytecode a stage's HLSL text compiles to (vkd3d-compiler's
// terms): for hlsl_dx9, vs_3_0/ps_3_0 as d3dbc; for hlsl_dx10, vs_4_0/ps_4_0
// as dxbc-tpf.
struct BytecodeFormat {
  std::string profile;          // "vs_3_0", "ps_3_0", "vs_4_0", "ps_4_0"
  std::string_view vkd3d_type;  // vkd3d-compiler's -b: "d3dbc" or "dxbc-tpf"
  std::string_view extension;   // ".d3dbc" or ".dxbc", replacing the text's ".hlsl"
};

// The target's bytecode for `stage`; none for a target that is not HLSL.
std::optional<BytecodeFormat> bytecode_format(Target target, ShaderStage stage);

// File name of a stage's output, e.g. "query.frag.spv", "query.frag", "query.frag.hlsl".
std::string output_file_name(Target target, std::string_view pass_file, ShaderStage stage);

}  // namespace penumbra
