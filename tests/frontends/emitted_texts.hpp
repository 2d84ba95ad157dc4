// The texts the library emits, in memory: every default variant's passes
// compiled for a target (compile_pass), as test inputs.
#pragma once

#include <string>
#include <vector>

#include "penumbra/compiler/build.hpp"
#include "penumbra/model/model.hpp"

namespace penumbra::testing {

struct EmittedStage {
  PassKind pass = PassKind::query;
  ShaderStage stage = ShaderStage::vertex;
  std::string name;        // "pcf_grid_k3/glsl330/query.frag", for messages
  CompiledStage compiled;  // text, the target's SPIR-V and its reflection
};

// Every pass the variant uses (depth, the min-max build passes when its
// technique reads the mip, query), vertex and fragment stage, in that order.
// Fails the calling test (and returns fewer) when a pass does not compile.
std::vector<EmittedStage> emitted_stages(const Variant& variant, Target target);

}  // namespace penumbra::testing
