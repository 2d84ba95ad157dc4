#include "penumbra/compiler/targets.hpp"
#include "penumbra/support/text.hpp"

namespace penumbra {

std::string target_defines(Target target) {
  const TargetTraits t = traits(target);
  std::string out = "#define PENUMBRA_TARGET_" + ascii_upper(to_string(target)) + " 1\n";
  out += "#define PENUMBRA_HAS_COMPARISON_SAMPLER ";
  out += t.comparison_sampler ? "1\n" : "0\n";
  out += "#define PENUMBRA_DISK_TEXTURES ";
  out += t.disk_textures ? "1\n" : "0\n";
  // Direct3D's viewport puts clip-space y = +1 in a target's row 0; Direct3D's
  // and Vulkan's projections map depth to clip z / w in [0, 1], OpenGL's (the
  // GLSL text targets', as the engines' gl_clip_depth) to [-1, 1]
  // (common/light_clip.glsl).
  out += "#define PENUMBRA_CLIP_Y_DOWN ";
  out += t.is_hlsl ? "1\n" : "0\n";
  out += "#define PENUMBRA_CLIP_Z_FROM_ZERO ";
  out += t.is_text && !t.is_hlsl ? "0\n" : "1\n";
  // PENUMBRA_SAMPLE_LOOP heads the loops over filter samples.
  out += "#define PENUMBRA_SAMPLE_LOOP";
  out += t.rolled_sample_loops ? " [[dont_unroll]]\n" : "\n";
  return out;
}

std::optional<BytecodeFormat> bytecode_format(Target target, ShaderStage stage) {
  const int model = traits(target).shader_model;
  if (model == 0) return std::nullopt;
  const std::string profile =
      std::string(stage == ShaderStage::vertex ? "vs_" : "ps_") + std::to_string(model) + "_0";
  // Shader model 3 is the Direct3D 9 bytecode; 4 and 5 the container of
  // Direct3D 10 and 11.
  if (model == 3) return BytecodeFormat{profile, "d3dbc", ".d3dbc"};
  return BytecodeFormat{profile, "dxbc-tpf", ".dxbc"};
}

std::string output_file_name(Target target, std::string_view pass_file, ShaderStage stage) {
  std::string name(pass_file);
  name += stage == ShaderStage::vertex ? ".vert" : ".frag";
  if (target == Target::spirv) return name + ".spv";
  if (traits(target).is_hlsl) return name + ".hlsl";
  return name;
}

}  // namespace penumbra
