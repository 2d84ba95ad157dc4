// Small hand-written SPIR-V modules for the target-rule tests: a fragment
// (or vertex) shader skeleton with common types, into which a test puts its
// own declarations and the body of main, assembled with SPIRV-Tools.
#pragma once

#include <gtest/gtest.h>

#include <spirv-tools/libspirv.hpp>
#include <string>
#include <vector>

#include "penumbra/compiler/stage.hpp"
#include "targets/rules.hpp"

namespace penumbra::testing {

struct ModuleText {
  std::string decorations{};  // OpDecorate / OpMemberDecorate lines
  std::string globals{};      // types, constants, variables and other functions' types
  std::string main_body{};    // after main's OpLabel %entry, up to and including its terminator
  std::string functions{};    // whole functions after main
  ShaderStage stage = ShaderStage::fragment;
};

inline std::string module_text(const ModuleText& m) {
  const bool fragment = m.stage == ShaderStage::fragment;
  return std::string("OpCapability Shader\nOpCapability ImageQuery\n") +
         "%glsl = OpExtInstImport \"GLSL.std.450\"\nOpMemoryModel Logical GLSL450\n" +
         (fragment ? "OpEntryPoint Fragment %main \"main\" %out\n"
                     "OpExecutionMode %main OriginUpperLeft\n"
                   : "OpEntryPoint Vertex %main \"main\" %out\n") +
         "OpDecorate %out Location 0\n" + m.decorations +
         "%void = OpTypeVoid\n%fn = OpTypeFunction %void\n%float = OpTypeFloat 32\n"
         "%v2float = OpTypeVector %float 2\n%v4float = OpTypeVector %float 4\n"
         "%int = OpTypeInt 32 1\n%uint = OpTypeInt 32 0\n%bool = OpTypeBool\n"
         "%float_0 = OpConstant %float 0\n%float_1 = OpConstant %float 1\n"
         "%int_0 = OpConstant %int 0\n%int_1 = OpConstant %int 1\n"
         "%int_n1 = OpConstant %int -1\n%int_10 = OpConstant %int 10\n"
         "%uv = OpConstantComposite %v2float %float_0 %float_1\n"
         "%ptr_out = OpTypePointer Output %v4float\n%out = OpVariable %ptr_out Output\n"
         "%ptr_int = OpTypePointer Function %int\n"
         "%image = OpTypeImage %float 2D 0 0 0 1 Unknown\n"
         "%sampled = OpTypeSampledImage %image\n"
         "%ptr_sampled = OpTypePointer UniformConstant %sampled\n"
         "%tex = OpVariable %ptr_sampled UniformConstant\n"
         "%dimage = OpTypeImage %float 2D 1 0 0 1 Unknown\n"
         "%dsampled = OpTypeSampledImage %dimage\n"
         "%ptr_dsampled = OpTypePointer UniformConstant %dsampled\n"
         "%cmp = OpVariable %ptr_dsampled UniformConstant\n" +
         m.globals + "%main = OpFunction %void None %fn\n%entry = OpLabel\n" + m.main_body +
         "OpFunctionEnd\n" + m.functions;
}

inline std::vector<std::uint32_t> assemble(const ModuleText& m) {
  spvtools::SpirvTools tools(SPV_ENV_UNIVERSAL_1_0);
  std::string messages;
  tools.SetMessageConsumer(
      [&messages](spv_message_level_t, const char*, const spv_position_t& at, const char* message) {
        messages += std::to_string(at.line) + ": " + message + "\n";
      });
  std::vector<std::uint32_t> words;
  EXPECT_TRUE(tools.Assemble(module_text(m), &words)) << messages;
  return words;
}

// A job for `target` holding the assembled module, named like the build's.
struct RuleJob {
  Variant variant;
  ShaderJob job;

  RuleJob(Target target, const ModuleText& m) {
    variant.name = "rules_test";
    job.variant = &variant;
    job.target = target;
    job.stage = m.stage;
    job.source_path = m.stage == ShaderStage::fragment ? "passes/query.frag" : "passes/depth.vert";
    job.spirv = assemble(m);
  }
  RuleJob(const RuleJob&) = delete;
  RuleJob& operator=(const RuleJob&) = delete;

  // "" when the rules pass, else the error as the build reports it.
  std::string check() {
    const Status status = check_target_rules(job);
    return status.ok() ? std::string() : status.error().to_string();
  }
};

inline std::string prefix(Target target, ShaderStage stage = ShaderStage::fragment) {
  return "variant rules_test, target " + std::string(to_string(target)) + ", " +
         (stage == ShaderStage::fragment ? "passes/query.frag" : "passes/depth.vert") + ": ";
}

// The end of main: writes the float `value` to %out as a splat vec4 (1 slot).
inline std::string store_out(const std::string& value) {
  return "%result = OpCompositeConstruct %v4float " + value + " " + value + " " + value + " " +
         value + "\nOpStore %out %result\nOpReturn\n";
}

// `for (i = init; i <compare> bound; i = i <step> 1) { body }` in glslang's
// memory form, for the start of main; the merge block %merge comes last.
struct Loop {
  std::string variables{};  // more OpVariable lines for the entry block
  std::string init = "%int_0";
  std::string compare = "OpSLessThan";
  std::string bound = "%int_10";
  std::string step = "OpIAdd";
  std::string body{};  // instructions of the %body block, before its branch to %continue
};

inline std::string loop_text(const Loop& loop) {
  return "%i = OpVariable %ptr_int Function\n" + loop.variables + "OpStore %i " + loop.init +
         "\nOpBranch %header\n%header = OpLabel\nOpLoopMerge %merge %continue None\n"
         "OpBranch %test\n%test = OpLabel\n%iv = OpLoad %int %i\n%lt = " +
         loop.compare + " %bool %iv " + loop.bound +
         "\nOpBranchConditional %lt %body %merge\n%body = OpLabel\n" + loop.body +
         "OpBranch %continue\n%continue = OpLabel\n%j = OpLoad %int %i\n%next = " + loop.step +
         " %int %j %int_1\nOpStore %i %next\nOpBranch %header\n%merge = OpLabel\n";
}

}  // namespace penumbra::testing
