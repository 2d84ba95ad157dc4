// The hlsl_dx9 register shim: every constant and sampler gets the explicit
// register that the reflection lists (docs/engines/d3d9.md).
// - SPIRV-Cross emits the uniform block as `cbuffer` even for Shader Model
//   3.0; each float4 member at `packoffset(cN)` becomes
//   `uniform float4 name : register(cN);`, the same register and meaning.
//   Every ShadowParams member is a float4, so nothing is repacked.
// - SPIRV-Cross's `gl_HalfPixel` (vertex shaders) takes the register after
//   ShadowParams, half_pixel_register(), in every vertex shader.
// - `uniform sampler2D name;` gets `register(s#)`, # its slot in shader_contract.hpp;
//   `prefix` heads the names (the function form's).
#pragma once

#include <string>
#include <string_view>

#include "penumbra/support/result.hpp"

namespace penumbra {

Result<std::string> dx9_explicit_registers(const std::string& hlsl, std::string_view prefix = {});

}  // namespace penumbra
