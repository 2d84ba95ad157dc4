// hlsl_dx9 rules on hand-written modules: each forbidden construct and each
// register limit stops the build with a message naming variant, target and
// construct; a module just inside the limits passes.
#include <gtest/gtest.h>

#include "spirv_fixture.hpp"

namespace penumbra {
namespace {

using testing::assemble;
using testing::ModuleText;
using testing::prefix;
using testing::RuleJob;
using testing::store_out;

constexpr const char* kImageTypes =
    "%v3float = OpTypeVector %float 3\n%v2int = OpTypeVector %int 2\n"
    "%proj = OpConstantComposite %v3float %float_0 %float_1 %float_1\n"
    "%texel = OpConstantComposite %v2int %int_0 %int_0\n";

struct ForbiddenCase {
  const char* name;
  const char* body;  // ends with a float %x
  const char* message;
};

const ForbiddenCase kForbidden[] = {
    {"SampleCmp",
     "%s = OpLoad %dsampled %cmp\n%x = OpImageSampleDrefImplicitLod %float %s %uv %float_0\n",
     "comparison sampling (SampleCmp) is not allowed for hlsl_dx9: SM 3.0 has no comparison "
     "samplers; compare in the shader"},
    {"SampleCmpLevelZero",
     "%s = OpLoad %dsampled %cmp\n"
     "%x = OpImageSampleDrefExplicitLod %float %s %uv %float_0 Lod %float_0\n",
     "comparison sampling (SampleCmpLevelZero) is not allowed for hlsl_dx9: SM 3.0 has no "
     "comparison samplers; compare in the shader"},
    {"tex2Dproj",
     "%s = OpLoad %sampled %tex\n%t = OpImageSampleProjExplicitLod %v4float %s %proj Lod "
     "%float_0\n%x = OpCompositeExtract %float %t 0\n",
     "tex2Dproj is not allowed for hlsl_dx9: projective lookups are not allowed"},
    {"textureSize",
     "%s = OpLoad %sampled %tex\n%im = OpImage %image %s\n"
     "%size = OpImageQuerySizeLod %v2int %im %int_0\n%w = OpCompositeExtract %int %size 0\n"
     "%x = OpConvertSToF %float %w\n",
     "textureSize is not allowed for hlsl_dx9: SM 3.0 has no texture-size query; pass sizes as "
     "constants"},
    {"texelFetch",
     "%s = OpLoad %sampled %tex\n%im = OpImage %image %s\n"
     "%t = OpImageFetch %v4float %im %texel Lod %int_0\n%x = OpCompositeExtract %float %t 0\n",
     "texelFetch is not allowed for hlsl_dx9: SM 3.0 has no texel fetch; sample texel centres"},
    {"Shift", "%b = OpShiftLeftLogical %int %int_1 %int_1\n%x = OpConvertSToF %float %b\n",
     "integer bit shift is not allowed for hlsl_dx9: SM 3.0 has no integer bit operations"},
    {"BitwiseAnd", "%b = OpBitwiseAnd %int %int_1 %int_10\n%x = OpConvertSToF %float %b\n",
     "integer bitwise and is not allowed for hlsl_dx9: SM 3.0 has no integer bit operations"},
};

class Dx9Forbidden : public ::testing::TestWithParam<ForbiddenCase> {};

TEST_P(Dx9Forbidden, StopsTheBuildNamingTheConstruct) {
  const ForbiddenCase& c = GetParam();
  RuleJob rule(Target::hlsl_dx9, {.globals = kImageTypes, .main_body = c.body + store_out("%x")});
  EXPECT_EQ(rule.check(), prefix(Target::hlsl_dx9) + c.message);
  // The same module is fine for a target with comparison samplers and bit operations.
  RuleJob glsl(Target::glsl450, {.globals = kImageTypes, .main_body = c.body + store_out("%x")});
  EXPECT_EQ(glsl.check(), "");
}

INSTANTIATE_TEST_SUITE_P(Constructs, Dx9Forbidden, ::testing::ValuesIn(kForbidden),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

// The skeleton declares two samplers (%tex, %cmp); `more` adds an array of them.
ModuleText with_samplers(int more, ShaderStage stage) {
  return {.globals = "%uint_n = OpConstant %uint " + std::to_string(more) +
                     "\n%many_t = OpTypeArray %sampled %uint_n\n"
                     "%ptr_many = OpTypePointer UniformConstant %many_t\n"
                     "%many = OpVariable %ptr_many UniformConstant\n",
          .main_body = store_out("%float_1"),
          .stage = stage};
}

TEST(Dx9Samplers, SixteenPassSeventeenStopTheBuild) {
  RuleJob sixteen(Target::hlsl_dx9, with_samplers(14, ShaderStage::fragment));
  EXPECT_EQ(sixteen.check(), "");
  RuleJob seventeen(Target::hlsl_dx9, with_samplers(15, ShaderStage::fragment));
  EXPECT_EQ(seventeen.check(),
            prefix(Target::hlsl_dx9) +
                "using 17 samplers is not allowed for hlsl_dx9: ps_3_0 has 16 sampler registers "
                "(s0-s15)");
}

TEST(Dx9Samplers, VertexShadersHaveFour) {
  RuleJob five(Target::hlsl_dx9, with_samplers(3, ShaderStage::vertex));
  EXPECT_EQ(five.check(), prefix(Target::hlsl_dx9, ShaderStage::vertex) +
                              "using 5 samplers is not allowed for hlsl_dx9: vs_3_0 has 4 "
                              "sampler registers (s0-s3)");
}

// A two-register uniform block and a `static const float2 disk[n]`.
ModuleText with_disk(int n) {
  std::string disk = "%disk = OpConstantComposite %disk_t";
  for (int k = 0; k < n; ++k) disk += " %uv";
  return {.decorations =
              "OpMemberDecorate %Params 0 Offset 0\nOpMemberDecorate %Params 1 "
              "Offset 16\nOpDecorate %Params Block\n",
          .globals =
              "%Params = OpTypeStruct %v4float %v4float\n"
              "%ptr_params = OpTypePointer Uniform %Params\n"
              "%params = OpVariable %ptr_params Uniform\n%uint_n = OpConstant %uint " +
              std::to_string(n) + "\n%disk_t = OpTypeArray %v2float %uint_n\n" + disk + "\n",
          .main_body = store_out("%float_1")};
}

TEST(Dx9ConstantRegisters, BlocksAndStaticArraysShareThePs30Registers) {
  RuleJob full(Target::hlsl_dx9, with_disk(222));
  EXPECT_EQ(full.check(), "");
  RuleJob over(Target::hlsl_dx9, with_disk(223));
  EXPECT_EQ(over.check(), prefix(Target::hlsl_dx9) +
                              "using 225 constant registers (uniform blocks 2, static const "
                              "arrays 223) is not allowed for hlsl_dx9: ps_3_0 has 224 float4 "
                              "constant registers (c0-c223)");
}

// A uniform block holding `vec4 lights[n]` (ArrayStride 16).
ModuleText with_uniform_array(int n, ShaderStage stage) {
  return {.decorations =
              "OpDecorate %lights_t ArrayStride 16\nOpMemberDecorate %Big 0 Offset "
              "0\nOpDecorate %Big Block\n",
          .globals = "%uint_n = OpConstant %uint " + std::to_string(n) +
                     "\n%lights_t = OpTypeArray %v4float %uint_n\n%Big = OpTypeStruct %lights_t\n"
                     "%ptr_big = OpTypePointer Uniform %Big\n%big = OpVariable %ptr_big Uniform\n",
          .main_body = store_out("%float_1"),
          .stage = stage};
}

TEST(Dx9ConstantRegisters, UniformBlockSizeComesFromItsLayout) {
  RuleJob fragment(Target::hlsl_dx9, with_uniform_array(250, ShaderStage::fragment));
  EXPECT_EQ(fragment.check(), prefix(Target::hlsl_dx9) +
                                  "using 250 constant registers (uniform blocks 250, static "
                                  "const arrays 0) is not allowed for hlsl_dx9: ps_3_0 has 224 "
                                  "float4 constant registers (c0-c223)");
  RuleJob vertex(Target::hlsl_dx9, with_uniform_array(250, ShaderStage::vertex));
  EXPECT_EQ(vertex.check(), "");  // vs_3_0 has 256
}

TEST(Dx9Rules, TheSkeletonItselfPasses) {
  EXPECT_FALSE(assemble({.main_body = store_out("%float_1")}).empty());
  RuleJob plain(Target::hlsl_dx9, {.main_body = store_out("%float_1")});
  EXPECT_EQ(plain.check(), "");
}

}  // namespace
}  // namespace penumbra
