// What a pass runs with: SPIR-V stages with their reflection, and the values
// of the ShadowParams uniform block (docs/shader-interface.md).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
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
struct PassProgram {
  StageCode vert;
  StageCode frag;
};

// ShadowParams member name -> its vec4 value, e.g. "light" -> {L, Fw, n, L/Fw}.
// Every member the program's block declares must be present; extra entries
// are ignored, so one ParamBlock can serve every pass.
using ParamBlock = std::map<std::string, std::array<float, 4>>;

}  // namespace penumbra
