#include "text_programs.hpp"

#include <gtest/gtest.h>

#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/targets.hpp"
#include "penumbra/compiler/text_frontend.hpp"
#include "test_programs.hpp"

namespace penumbra::test {
namespace {

StageCode reflected(std::vector<std::uint32_t> spirv, const std::string& name) {
  StageCode stage{std::move(spirv), {}};
  auto iface = reflect(stage.spirv);
  if (!iface) {
    ADD_FAILURE() << name << ": " << iface.error().to_string();
    return stage;
  }
  stage.iface = std::move(*iface);
  return stage;
}

StageCode text_stage(const CompiledStage& compiled, Target target, ShaderStage stage,
                     const std::string& name) {
  if (target == Target::spirv) return reflected(compiled.spirv, name);
  auto spirv = compile_target_text(target, stage, compiled.text, name);
  if (!spirv) {
    ADD_FAILURE() << spirv.error().to_string();
    return {};
  }
  return reflected(std::move(spirv->spirv), name);
}

}  // namespace

StageCode reflected_stage(const std::string& name) {
  return reflected(read_spirv(name), name);
}

PassProgram text_program(const std::string& variant, PassKind pass, Target target) {
  PassProgram program;
  const CompiledPass* compiled = compiled_pass(variant, pass, target);
  if (!compiled) return program;
  const std::string name =
      variant + "/" + std::string(to_string(target)) + "/" + std::string(to_string(pass)) + ".";
  program.vert = text_stage(compiled->vert, target, ShaderStage::vertex, name + "vert");
  program.frag = text_stage(compiled->frag, target, ShaderStage::fragment, name + "frag");
  program.target = target;
  program.reflection = compiled->reflection;
  // As load_executable: each API's clip-space conventions.
  if (target != Target::spirv) {
    program.d3d_viewport = traits(target).is_hlsl;
    program.gl_clip_depth = !traits(target).is_hlsl;
  }
  return program;
}

}  // namespace penumbra::test
