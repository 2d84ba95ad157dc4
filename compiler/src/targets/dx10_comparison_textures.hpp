// The comparison-texture shim of Shader Model 4.0 and later (hlsl_dx10,
// hlsl_dx11). SPIRV-Cross declares every texture `Texture2D<float4>`; a
// texture read only with SampleCmp, whose result is a scalar, is declared
// `Texture2D<float>` instead (a map_layout array's `Texture2DArray<float>`), so that compilers
// which type SampleCmpLevelZero by the template (vkd3d-compiler) see no vector truncation (W5300).
// The resource, its register and its reads are unchanged. `prefix` heads the texture names (the
// function form's).
#pragma once

#include <string>
#include <string_view>

namespace penumbra {

std::string dx10_comparison_textures_as_scalar(const std::string& hlsl,
                                               std::string_view prefix = {});

}  // namespace penumbra
