// What distinguishes one target from another, in one place: the defines the
// shader source sees and the file names of its output.
#pragma once

#include <string>
#include <string_view>

#include "penumbra/compiler/reflection.hpp"
#include "penumbra/model/model.hpp"

namespace penumbra {

struct TargetTraits {
  bool comparison_sampler = true;  // has sampler2DShadow / SampleCmp; false for hlsl_dx9
  bool is_hlsl = false;            // HLSL text (y flipped for D3D's viewport)
  bool is_text = true;             // false for spirv (binary output)
};

TargetTraits traits(Target target);

// `#define` lines for the target, included into every shader via variant.glsl.
std::string target_defines(Target target);

// File name of a stage's output, e.g. "query.frag.spv", "query.frag", "query.frag.hlsl".
std::string output_file_name(Target target, std::string_view pass_file, ShaderStage stage);

}  // namespace penumbra
