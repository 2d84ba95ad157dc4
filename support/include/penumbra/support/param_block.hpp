// ParamBlock: the values of ShadowParams' members, as both engines take them,
// and the rule naming the entry a reflected member reads.
#pragma once

#include <array>
#include <map>
#include <string>
#include <string_view>

namespace penumbra {

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
