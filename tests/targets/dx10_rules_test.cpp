// The rules of Shader Model 4.0 and later (hlsl_dx10, hlsl_dx11) on
// hand-written modules: no gradients inside loops (found through calls too),
// and SampleLevel / SampleCmpLevelZero as the only sampling.
#include <gtest/gtest.h>

#include "spirv_fixture.hpp"

namespace penumbra {
namespace {

using testing::loop_text;
using testing::prefix;
using testing::RuleJob;
using testing::store_out;

const std::string kInLoop =
    " inside a loop is not allowed for hlsl_dx10: gradients in a loop make FXC unroll it or "
    "fail (X3570); sample with SampleLevel or take derivatives before the loop";
const std::string kSamplingOnly =
    " is not allowed for hlsl_dx10: the library samples with SampleLevel and "
    "SampleCmpLevelZero only";

std::string check_dx10(const std::string& body, const std::string& functions = "") {
  RuleJob rule(Target::hlsl_dx10, {.globals = "%float_fn = OpTypeFunction %float\n",
                                   .main_body = body,
                                   .functions = functions});
  return rule.check();
}

std::string in_loop(const std::string& loop_body) {
  return loop_text({.body = loop_body}) + store_out("%float_1");
}

constexpr const char* kImplicitSample =
    "%s = OpLoad %sampled %tex\n%t = OpImageSampleImplicitLod %v4float %s %uv\n";

TEST(Dx10Rules, ImplicitLodSamplingInsideALoop) {
  EXPECT_EQ(check_dx10(in_loop(kImplicitSample)),
            prefix(Target::hlsl_dx10) + "implicit-LOD sampling (Sample)" + kInLoop);
}

TEST(Dx10Rules, DerivativeInsideALoop) {
  EXPECT_EQ(check_dx10(in_loop("%d = OpDPdx %float %float_1\n")),
            prefix(Target::hlsl_dx10) + "derivative (ddx)" + kInLoop);
}

TEST(Dx10Rules, DerivativeInAFunctionCalledInsideALoop) {
  const std::string slope =
      "%slope = OpFunction %float None %float_fn\n%slope_entry = OpLabel\n"
      "%w = OpFwidth %float %float_1\nOpReturnValue %w\nOpFunctionEnd\n";
  EXPECT_EQ(check_dx10(in_loop("%r = OpFunctionCall %float %slope\n"), slope),
            prefix(Target::hlsl_dx10) + "derivative (fwidth)" + kInLoop);
  // Called outside the loop, the same function is fine.
  EXPECT_EQ(check_dx10("%r = OpFunctionCall %float %slope\n" + store_out("%r"), slope), "");
}

TEST(Dx10Rules, DerivativeOutsideLoopsIsAllowed) {
  EXPECT_EQ(check_dx10("%d = OpDPdy %float %float_1\n" + store_out("%d")), "");
}

TEST(Dx10Rules, ImplicitLodSamplingAnywhere) {
  EXPECT_EQ(check_dx10(std::string(kImplicitSample) + store_out("%float_1")),
            prefix(Target::hlsl_dx10) + "implicit-LOD sampling (Sample)" + kSamplingOnly);
}

TEST(Dx10Rules, GradientSampling) {
  EXPECT_EQ(check_dx10("%s = OpLoad %sampled %tex\n"
                       "%t = OpImageSampleExplicitLod %v4float %s %uv Grad %uv %uv\n" +
                       store_out("%float_1")),
            prefix(Target::hlsl_dx10) + "gradient sampling (SampleGrad)" + kSamplingOnly);
}

// GLSL's way to compare at level 0 in a sampler2DArrayShadow: zero
// gradients, which SampleCmpLevelZero is; any other gradient is refused.
TEST(Dx10Rules, ComparisonWithZeroGradientsIsLevelZero) {
  const auto compare_with = [](const std::string& gradients) {
    RuleJob rule(Target::hlsl_dx10,
                 {.globals = "%zero = OpConstantComposite %v2float %float_0 %float_0\n"
                             "%null = OpConstantNull %v2float\n",
                  .main_body = "%s = OpLoad %dsampled %cmp\n"
                               "%c = OpImageSampleDrefExplicitLod %float %s %uv %float_0 Grad " +
                               gradients + "\n" + store_out("%c")});
    return rule.check();
  };
  EXPECT_EQ(compare_with("%zero %null"), "");
  EXPECT_EQ(compare_with("%zero %uv"),
            prefix(Target::hlsl_dx10) + "gradient sampling (SampleGrad)" + kSamplingOnly);
}

TEST(Dx10Rules, ComparisonAtALevelOtherThanZero) {
  EXPECT_EQ(check_dx10("%s = OpLoad %dsampled %cmp\n"
                       "%c = OpImageSampleDrefExplicitLod %float %s %uv %float_0 Lod %float_1\n" +
                       store_out("%c")),
            prefix(Target::hlsl_dx10) +
                "comparison sampling at a level other than 0 (SampleCmpLevel)" + kSamplingOnly);
}

TEST(Dx10Rules, Gather) {
  EXPECT_EQ(check_dx10("%s = OpLoad %sampled %tex\n"
                       "%g = OpImageGather %v4float %s %uv %int_0\n" +
                       store_out("%float_1")),
            prefix(Target::hlsl_dx10) + "gather (Gather)" + kSamplingOnly);
}

TEST(Dx10Rules, SampleLevelAndSampleCmpLevelZeroInsideLoopsAreAllowed) {
  const std::string body =
      "%s = OpLoad %sampled %tex\n%t = OpImageSampleExplicitLod %v4float %s %uv Lod %float_0\n"
      "%d = OpLoad %dsampled %cmp\n"
      "%c = OpImageSampleDrefExplicitLod %float %d %uv %float_0 Lod %float_0\n";
  EXPECT_EQ(check_dx10(in_loop(body)), "");
}

// hlsl_dx11 has the same rules, by its shader model; the message names it.
TEST(Dx10Rules, Direct3D11HasTheSameRules) {
  RuleJob rule(Target::hlsl_dx11, {.main_body = in_loop(kImplicitSample)});
  EXPECT_EQ(rule.check(), prefix(Target::hlsl_dx11) + "implicit-LOD sampling (Sample)" +
                              " inside a loop is not allowed for hlsl_dx11: gradients in a loop "
                              "make FXC unroll it or fail (X3570); sample with SampleLevel or take "
                              "derivatives before the loop");
}

TEST(Dx10Rules, OtherTargetsMaySampleWithGradients) {
  for (Target target : {Target::spirv, Target::glsl450, Target::glsl330, Target::essl300}) {
    RuleJob rule(target, {.main_body = in_loop(kImplicitSample)});
    EXPECT_EQ(rule.check(), "") << to_string(target);
  }
}

}  // namespace
}  // namespace penumbra
