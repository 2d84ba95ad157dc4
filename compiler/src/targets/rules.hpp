// Target rules: constructs and limits a target cannot express, checked on the
// SPIR-V compiled for that target before emitting, so that the message names
// the variant, the target and the construct (docs/targets.md lists them).
#pragma once

#include "penumbra/compiler/stage.hpp"
#include "penumbra/spirv/module.hpp"

namespace penumbra {

// Checks job.spirv against the rules of job.target.
Status check_target_rules(ShaderJob& job);

// hlsl_dx9 (dx9_rules.cpp): no comparison samplers, tex2Dproj, size queries,
// texel fetches or integer bit operations; sampler and constant registers
// within Shader Model 3.0's limits.
Status check_dx9_rules(ShaderJob& job, const SpirvModule& module);

// Shader Model 4.0 and later, hlsl_dx10 (dx10_rules.cpp): no gradients
// inside loops; SampleLevel and SampleCmpLevelZero are the only sampling.
Status check_dx10_rules(const ShaderJob& job, const SpirvModule& module);

}  // namespace penumbra
