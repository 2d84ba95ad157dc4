// The hlsl_dx9 register shim rewrites layout, never meaning.
#include "targets/dx9_registers.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace penumbra {
namespace {

using ::testing::HasSubstr;

TEST(Dx9Registers, Float4MembersBecomeRegisters) {
  const std::string in =
      "static float x;\ncbuffer ShadowParams : register(b0)\n{\n"
      "    float4 params_a : packoffset(c0);\n    float4 params_b : packoffset(c1);\n};\n"
      "float4 main() : COLOR0 { return params_b; }\n";
  auto out = dx9_explicit_registers(in);
  ASSERT_TRUE(out.ok());
  EXPECT_EQ(*out,
            "static float x;\n// ShadowParams as Direct3D 9 constant registers\n"
            "uniform float4 params_a : register(c0);\nuniform float4 params_b : register(c1);\n\n"
            "float4 main() : COLOR0 { return params_b; }\n");
}

TEST(Dx9Registers, HalfPixelIsPinnedAfterShadowParamsWithOrWithoutConstants) {
  const std::string with_block =
      "cbuffer P : register(b0)\n{\n    float4 params_a : packoffset(c0);\n"
      "    float4 params_b : packoffset(c3);\n};\nuniform float4 gl_HalfPixel;\n";
  const std::string pinned = "uniform float4 gl_HalfPixel : register(c6);";
  auto out = dx9_explicit_registers(with_block);
  ASSERT_TRUE(out.ok());
  EXPECT_THAT(*out, HasSubstr(pinned));
  auto alone = dx9_explicit_registers("uniform float4 gl_HalfPixel;\n");
  ASSERT_TRUE(alone.ok());
  EXPECT_THAT(*alone, HasSubstr(pinned));
}

TEST(Dx9Registers, ConstantsReachingTheHalfPixelRegisterAreRefused) {
  const std::string in =
      "cbuffer P : register(b0)\n{\n    float4 params_a : packoffset(c6);\n};\n"
      "uniform float4 gl_HalfPixel;\n";
  auto out = dx9_explicit_registers(in);
  ASSERT_FALSE(out.ok());
  EXPECT_THAT(out.error().message, HasSubstr("gl_HalfPixel is pinned at c6"));
}

TEST(Dx9Registers, SamplersTakeTheirContractSlot) {
  auto out = dx9_explicit_registers(
      "uniform sampler2D shadow_depth;\nuniform sampler2D receivers;\nfloat4 x;\n");
  ASSERT_TRUE(out.ok());
  EXPECT_EQ(*out,
            "uniform sampler2D shadow_depth : register(s1);\n"
            "uniform sampler2D receivers : register(s3);\nfloat4 x;\n");
}

TEST(Dx9Registers, AnUnknownSamplerIsRefusedNamingIt) {
  auto out = dx9_explicit_registers("uniform sampler2D mystery;\n");
  ASSERT_FALSE(out.ok());
  EXPECT_THAT(out.error().message, HasSubstr("'mystery'"));
}

TEST(Dx9Registers, APackedScalarIsRefusedNamingTheMember) {
  const std::string in =
      "cbuffer P : register(b0)\n{\n    float4 params_a : packoffset(c0);\n"
      "    float params_s : packoffset(c1.y);\n};\n";
  auto out = dx9_explicit_registers(in);
  ASSERT_FALSE(out.ok());
  EXPECT_THAT(out.error().message, HasSubstr("params_s"));
  EXPECT_THAT(out.error().message, HasSubstr("float4 registers"));
}

TEST(Dx9Registers, TextWithoutConstantsIsUnchanged) {
  const std::string in = "float4 main() : COLOR0 { return 1.0.xxxx; }\n";
  auto out = dx9_explicit_registers(in);
  ASSERT_TRUE(out.ok());
  EXPECT_EQ(*out, in);
}

}  // namespace
}  // namespace penumbra
