// The text rewrites a front end needs before it accepts a target's emitted
// text, all in one place. Each shim is exact (it changes only what its
// comment says) and never changes meaning; docs/frontends.md justifies each.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "penumbra/model/model.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

struct ShimmedText {
  std::string text;
  std::vector<std::string> shims;  // names of the shims that changed the text, in order
};

// Applies every shim of `target` in table order; a shim that finds nothing
// to rewrite is not named. An Error (message only) when the text is not of
// the shape a shim requires.
Result<ShimmedText> apply_shims(Target target, std::string_view text);

// "essl300-version-310": `#version 300 es` → `#version 310 es`, the first
// line only. glslang compiles ESSL to SPIR-V from 3.10 on. ESSL 3.10 adds
// features, keywords and relaxations to 3.00 and keeps the meaning of what
// 3.00 has (a 3.00 identifier that became a keyword fails to compile rather
// than change meaning); default precisions are the same. For every emitted
// file glslang's AST read as 3.00 and as 3.10 is the same, types and
// precisions included, except that 3.10 puts gl_Position in a gl_PerVertex
// block (tests/frontends/shims_test.cpp).
Result<std::string> essl300_version_as_310(std::string_view text);

// "dx9-output-semantics-as-sv": in the entry point's output struct
// (SPIRV_Cross_Output) only, `: POSITION;` → `: SV_Position;` and
// `: DEPTH;` → `: SV_Depth;`. glslang's HLSL front end, DX9-compatible or
// not, maps only the SV_ names to the Position and FragDepth built-ins and
// makes POSITION and DEPTH plain outputs at a location: nothing would reach
// the rasterizer or the depth buffer. As outputs, D3D9's POSITION is
// the clip-space position and DEPTH the pixel's depth: the meaning that
// Direct3D 10 renamed SV_Position and SV_Depth (POSITION as a vertex *input*
// is an attribute, which is why only the output struct is touched).
Result<std::string> dx9_output_semantics_as_system_values(std::string_view text);

}  // namespace penumbra
