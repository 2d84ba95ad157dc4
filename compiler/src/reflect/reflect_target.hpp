// One target's reflection of a pass (index.json `reflection.<pass>.<target>`),
// written from the shader contract and the SPIR-V reflection of each stage: the SPIR-V says which
// resources and members survived compilation, shader_contract.hpp and the target's rules say how
// the emitted text names, numbers and types them. Tests prove each record against the text with
// parsers of its own (tests/interface/).
#pragma once

#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/target_reflection.hpp"
#include "penumbra/spirv/reflection.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

// One stage's part of the pass's reflection: its bindings, and the vertex
// inputs (vertex stage) or the render targets, depth target and extensions
// (fragment stage). Errors (compile, where = the pass and target) name a
// resource shader_contract.hpp lacks or one whose binding differs from the
// one there, or a constant texture `variant` has no contents for. `encoding`
// is the map's (ShaderJob::map_encoding): the depth pass's depth test and the
// comparison sampler's function follow it. `prefix` heads every name the
// text declares (the function form's kFunctionPrefix).
Result<PassReflection> reflect_target(Target target, PassKind pass, const Variant* variant,
                                      MapEncoding encoding, const ShaderInterface& iface,
                                      std::string_view prefix = {});

// The pass's reflection from the parts of its two stages.
PassReflection join_stages(PassReflection vert, const PassReflection& frag);

}  // namespace penumbra
