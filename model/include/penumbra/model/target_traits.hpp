// What distinguishes one target from another, in one place: a row of
// target_traits.cpp per target, read by the compiler, the reflection and the
// engines instead of lists of targets.
#pragma once

#include <string_view>

#include "penumbra/model/model.hpp"

namespace penumbra {

// How a target's text declares its resources, and so how its reflection
// names them and where an engine binds them (target_reflection.hpp's table).
// Targets of one API generation share one: Direct3D 11 binds as Direct3D 10.
enum class ReflectionDialect {
  spirv,    // set and binding
  glsl450,  // binding, GL names
  glsl330,  // GL names; ShadowParams as loose uniforms
  essl300,  // GL names; ShadowParams as a std140 block
  d3d10,    // cbuffer b#, Texture2D t#, sampler objects s#, DXGI formats
  d3d9,     // constant registers c#, sampler2D s#, D3DFMT formats
};

struct TargetTraits {
  std::string_view name;  // manifests' and index.json's name: "hlsl_dx10"
  ReflectionDialect dialect = ReflectionDialect::spirv;
  bool comparison_sampler = true;  // has sampler2DShadow / SampleCmp; false for hlsl_dx9
  bool is_hlsl = false;            // HLSL text (y flipped for D3D's viewport)
  bool is_text = true;             // false for spirv (binary output)
  int shader_model = 0;            // HLSL: the Direct3D bytecode's shader model (3, 4, 5); else 0
  // Reads Poisson disks from the pcf_disk/blocker_disk textures rather than
  // constant arrays (hlsl_dx9: Shader Model 3 indexes those by compare chains).
  bool disk_textures = false;
  // Keeps the per-sample loops rolled (HLSL [loop]): Direct3D compilers
  // unroll at compile time, which takes minutes at the largest sample
  // counts and overflows ps_3_0's 512 instruction slots.
  bool rolled_sample_loops = false;
  // Caps the steps of a min-max walk (0: no cap) so that a shader stays
  // within the executed instructions every device runs: hlsl_dx9, for
  // ps_3_0's 65,535. At most 255, one ps_3_0 loop, so that the cap is exact.
  int walk_step_limit = 0;
  // Has integers and bit operations (false for hlsl_dx9: Shader Model 3
  // computes in floats only), which bitmask_backprojection needs.
  bool integer_ops = true;
  // Has 2D array textures (false for hlsl_dx9: Direct3D 9 has none), which
  // map_layout array reads.
  bool texture_arrays = true;
};

TargetTraits traits(Target target);

}  // namespace penumbra
