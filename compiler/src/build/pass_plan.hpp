// Which shaderlib files make up each pass, and where their output goes.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "penumbra/compiler/stage.hpp"
#include "penumbra/model/shader_contract.hpp"

namespace penumbra {

struct PassStageSource {
  PassKind pass;
  ShaderStage stage;
  std::string_view source;     // shaderlib path
  std::string_view file_stem;  // output name before the stage suffix
  bool per_variant;            // false: shared by every variant of a target
};

// Every pass of every technique, from shader_contract.hpp's pass
// descriptions; a pass's vertex stage comes first. The min-max build passes
// and screen_blur's blur and composite passes share passes/fullscreen.vert,
// compiled once per pass. Which passes a variant runs: runs_pass().
std::span<const PassStageSource> pass_plan();

// "spirv/common/depth.vert.spv", "hlsl_dx9/pcss_b16_p16_whitepaper16/query.frag.hlsl";
// a shared pass for a map encoding other than linear gets the encoding's
// name: "spirv/common/depth_perspective.vert.spv".
std::string output_path(const PassStageSource& source, Target target, const Variant* variant,
                        MapEncoding encoding);

// The map encoding `source` is compiled for when `variant` runs it: the
// variant's own for its own shaders, for the depth pass, which writes the
// map, and for minmax_init's fragment shader, which decodes it; linear for
// every other shared shader, which does not depend on it.
MapEncoding job_encoding(const PassStageSource& source, const Variant& variant);

// A job for `source`, ready to run through the pipeline: `variant`'s own,
// or for a shared pass the one that serves `variant`'s map encoding.
ShaderJob make_job(const PassStageSource& source, Target target, const Variant& variant);

// The function form of `variant` for `target`, a text target, written to
// "<target>/<variant>/penumbra_visibility.glsl" (".hlsl" for HLSL).
ShaderJob make_function_job(Target target, const Variant& variant);

}  // namespace penumbra
