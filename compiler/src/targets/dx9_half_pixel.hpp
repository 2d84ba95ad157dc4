// The hlsl_dx9 half-pixel shim: SPIRV-Cross's Direct3D 9 fixup moves the
// position by gl_HalfPixel in GL's clip space (y up), but our SPIR-V is
// Vulkan's (y down) and is flipped after the fixup (flip_vert_y). Its y term
// then moves the geometry half a pixel down instead of up. The shim turns
// the term's sign, so that gl_HalfPixel = (1/width, 1/height) shifts by
// (-1/2, -1/2) pixel in window coordinates: D3D9's pixel centres at integer
// coordinates then sample the points every other API samples
// (docs/engines/d3d9.md).
#pragma once

#include <string>

#include "penumbra/support/result.hpp"

namespace penumbra {

// `hlsl` with the y half-pixel term turned; an error when a vertex shader's
// fixup is not the one SPIRV-Cross emits (a new version changed it).
Result<std::string> dx9_half_pixel_after_flip(const std::string& hlsl);

}  // namespace penumbra
