// The hlsl_dx9 constant-register shim. SPIRV-Cross emits the uniform block
// as `cbuffer` even for Shader Model 3.0; Direct3D 9 engines set constants by
// register. This rewrites each float4 member at `packoffset(cN)` into
// `uniform float4 name : register(cN);` — the same register, the same
// meaning. Every ShadowParams member is a float4, so nothing is repacked.
// SPIRV-Cross's `gl_HalfPixel` (vertex shaders) gets the next free register.
#pragma once

#include <string>

#include "penumbra/support/result.hpp"

namespace penumbra {

Result<std::string> dx9_constants_as_registers(const std::string& hlsl);

}  // namespace penumbra
