// The ps_3_0 slot estimate on hand-written modules whose slot count follows
// from the model in docs/targets.md, and the warning (not an error) that an
// estimate over 512 slots gives.
#include "targets/slot_estimate.hpp"

#include <gtest/gtest.h>

#include "spirv_fixture.hpp"

namespace penumbra {
namespace {

using testing::Loop;
using testing::loop_text;
using testing::ModuleText;
using testing::prefix;
using testing::RuleJob;
using testing::store_out;

int estimate(const ModuleText& text) {
  const std::vector<std::uint32_t> words = testing::assemble(text);
  return estimate_ps30_slots(SpirvModule(words));
}

TEST(SlotEstimate, StraightLineCostsEachInstructionAsItsPs30Form) {
  const std::string body =
      "%s = OpLoad %sampled %tex\n"
      "%t = OpImageSampleExplicitLod %v4float %s %uv Lod %float_0\n"          // texldl: 2
      "%x = OpCompositeExtract %float %t 0\n"                                 // a swizzle: 0
      "%m = OpFMul %float %x %x\n"                                            // folded into the mad
      "%a = OpFAdd %float %m %float_1\n"                                      // mad: 1
      "%d = OpFDiv %float %a %x\n";                                           // rcp, mul: 2
  EXPECT_EQ(estimate({.main_body = body + store_out("%d")}), 2 + 1 + 2 + 1);  // + mov oC0
}

TEST(SlotEstimate, BothArmsOfABranchAndItsFlowControlCount) {
  const std::string body =
      "%c = OpFOrdLessThan %bool %float_0 %float_1\n"  // 1
      "OpSelectionMerge %join None\nOpBranchConditional %c %then %else\n"
      "%then = OpLabel\n%va = OpFAdd %float %float_0 %float_1\nOpBranch %join\n"  // 1
      "%else = OpLabel\n%vb = OpFSub %float %float_1 %float_0\nOpBranch %join\n"  // 1
      "%join = OpLabel\n%v = OpPhi %float %va %then %vb %else\n";
  EXPECT_EQ(estimate({.main_body = body + store_out("%v")}), 1 + (3 + 1 + 1) + 1 + 1 + 1);
}

TEST(SlotEstimate, CallsAreInlinedAtEveryCallSite) {
  const std::string tap =
      "%tap = OpFunction %float None %float_fn\n%tap_entry = OpLabel\n"
      "%s = OpLoad %sampled %tex\n%t = OpImageSampleExplicitLod %v4float %s %uv Lod %float_0\n"
      "%x = OpCompositeExtract %float %t 0\n%y = OpFMul %float %x %float_1\n"
      "OpReturnValue %y\nOpFunctionEnd\n";  // 2 + 1
  const std::string body =
      "%r1 = OpFunctionCall %float %tap\n%r2 = OpFunctionCall %float %tap\n"
      "%sum = OpFAdd %float %r1 %r2\n";
  EXPECT_EQ(estimate({.globals = "%float_fn = OpTypeFunction %float\n",
                      .main_body = body + store_out("%sum"),
                      .functions = tap}),
            3 + 3 + 1 + 1);
}

// A loop summing one texldl per iteration; `indexed` reads the coordinate
// from a constant array at [i], which ps_3_0 can only do unrolled.
ModuleText sampling_loop(Loop loop, bool indexed) {
  loop.variables =
      "%sum = OpVariable %ptr_float Function\n%copy = OpVariable %ptr_disk Function\n"
      "OpStore %sum %float_0\n";
  loop.body = std::string("%k = OpLoad %int %i\nOpStore %copy %disk\n") +
              "%at = OpAccessChain %ptr_v2 %copy " + (indexed ? "%k" : "%int_0") +
              "\n%p = OpLoad %v2float %at\n%s = OpLoad %sampled %tex\n"
              "%t = OpImageSampleExplicitLod %v4float %s %p Lod %float_0\n"  // 2
              "%x = OpCompositeExtract %float %t 0\n%old = OpLoad %float %sum\n"
              "%new = OpFAdd %float %old %x\nOpStore %sum %new\n";  // 1
  return {.globals =
              "%uint_4 = OpConstant %uint 4\n%disk_t = OpTypeArray %v2float %uint_4\n"
              "%disk = OpConstantComposite %disk_t %uv %uv %uv %uv\n"
              "%ptr_disk = OpTypePointer Function %disk_t\n"
              "%ptr_v2 = OpTypePointer Function %v2float\n"
              "%ptr_float = OpTypePointer Function %float\n"
              "%int_3 = OpConstant %int 3\n%int_200 = OpConstant %int 200\n"
              "%int_170 = OpConstant %int 170\n",
          .main_body = loop_text(loop) + "%total = OpLoad %float %sum\n" + store_out("%total")};
}

TEST(SlotEstimate, DynamicIndexingUnrollsTheLoopTripCountTimes) {
  EXPECT_EQ(estimate(sampling_loop({}, true)), 10 * 3 + 1);
}

TEST(SlotEstimate, OtherLoopsStayRolled) {
  // loop, endloop; the body once; the counter's add.
  EXPECT_EQ(estimate(sampling_loop({}, false)), 3 + 2 + 3 + 1 + 1);
}

TEST(SlotEstimate, TripCountsFollowTheLoopsConstantBounds) {
  EXPECT_EQ(estimate(sampling_loop(
                {.init = "%int_n1", .compare = "OpSLessThanEqual", .bound = "%int_1"}, true)),
            3 * 3 + 1);  // -1, 0, 1
  EXPECT_EQ(
      estimate(sampling_loop(
          {.init = "%int_10", .compare = "OpSGreaterThan", .bound = "%int_3", .step = "OpISub"},
          true)),
      7 * 3 + 1);  // 10 down to 4
}

TEST(SlotEstimate, OverTheMinimumIsAWarningNamingVariantTargetAndEstimate) {
  RuleJob over(Target::hlsl_dx9, sampling_loop({.bound = "%int_200"}, true));
  EXPECT_EQ(over.check(), "");  // not an error: many ps_3_0 devices run more
  EXPECT_EQ(over.job.estimated_slots, 601);
  ASSERT_EQ(over.job.diagnostics.size(), 1u);
  EXPECT_EQ(over.job.diagnostics[0].severity, Severity::warning);
  EXPECT_EQ(over.job.diagnostics[0].where + ": " + over.job.diagnostics[0].message,
            prefix(Target::hlsl_dx9) +
                "an estimated 601 ps_3_0 instruction slots for hlsl_dx9, over the 512 every "
                "ps_3_0 device runs; it needs a device whose MaxPixelShader30InstructionSlots "
                "allows more (docs/targets.md)");

  RuleJob under(Target::hlsl_dx9, sampling_loop({.bound = "%int_170"}, true));
  EXPECT_EQ(under.check(), "");
  EXPECT_EQ(under.job.estimated_slots, 511);
  EXPECT_TRUE(under.job.diagnostics.empty());
}

TEST(SlotEstimate, OnlyHlslDx9FragmentShadersAreEstimated) {
  RuleJob dx10(Target::hlsl_dx10, sampling_loop({.bound = "%int_200"}, true));
  EXPECT_EQ(dx10.check(), "");
  EXPECT_EQ(dx10.job.estimated_slots, 0);
  ModuleText vertex = sampling_loop({.bound = "%int_200"}, true);
  vertex.stage = ShaderStage::vertex;
  RuleJob dx9_vertex(Target::hlsl_dx9, vertex);
  EXPECT_EQ(dx9_vertex.check(), "");
  EXPECT_EQ(dx9_vertex.job.estimated_slots, 0);
  EXPECT_TRUE(dx9_vertex.job.diagnostics.empty());
}

}  // namespace
}  // namespace penumbra
