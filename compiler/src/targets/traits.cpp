#include "penumbra/compiler/targets.hpp"
#include "penumbra/support/text.hpp"

namespace penumbra {

TargetTraits traits(Target target) {
  switch (target) {
    case Target::spirv:
      return {.comparison_sampler = true, .is_hlsl = false, .is_text = false};
    case Target::glsl450:
    case Target::glsl330:
    case Target::essl300:
      return {.comparison_sampler = true, .is_hlsl = false, .is_text = true};
    case Target::hlsl_dx10:
      return {.comparison_sampler = true, .is_hlsl = true, .is_text = true};
    case Target::hlsl_dx9:
      // SM 3.0 has no comparison sampler: compares are made in the shader.
      return {.comparison_sampler = false, .is_hlsl = true, .is_text = true};
  }
  return {};
}

std::string target_defines(Target target) {
  std::string out = "#define PENUMBRA_TARGET_" + ascii_upper(to_string(target)) + " 1\n";
  out += "#define PENUMBRA_HAS_COMPARISON_SAMPLER ";
  out += traits(target).comparison_sampler ? "1\n" : "0\n";
  return out;
}

std::string output_file_name(Target target, std::string_view pass_file, ShaderStage stage) {
  std::string name(pass_file);
  name += stage == ShaderStage::vertex ? ".vert" : ".frag";
  if (target == Target::spirv) return name + ".spv";
  if (traits(target).is_hlsl) return name + ".hlsl";
  return name;
}

}  // namespace penumbra
