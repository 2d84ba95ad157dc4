// The hlsl_dx9 constant-register shim rewrites layout, never meaning.
#include "targets/dx9_constants.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace penumbra {
namespace {

using ::testing::HasSubstr;

TEST(Dx9Constants, Float4MembersBecomeRegisters) {
  const std::string in =
      "static float x;\ncbuffer ShadowParams : register(b0)\n{\n"
      "    float4 params_a : packoffset(c0);\n    float4 params_b : packoffset(c1);\n};\n"
      "float4 main() : COLOR0 { return params_b; }\n";
  auto out = dx9_constants_as_registers(in);
  ASSERT_TRUE(out.ok());
  EXPECT_EQ(*out,
            "static float x;\n// ShadowParams as Direct3D 9 constant registers\n"
            "uniform float4 params_a : register(c0);\nuniform float4 params_b : register(c1);\n\n"
            "float4 main() : COLOR0 { return params_b; }\n");
}

TEST(Dx9Constants, HalfPixelGetsTheRegisterAfterTheBlock) {
  const std::string in =
      "cbuffer P : register(b0)\n{\n    float4 params_a : packoffset(c0);\n"
      "    float4 params_b : packoffset(c3);\n};\nuniform float4 gl_HalfPixel;\n";
  auto out = dx9_constants_as_registers(in);
  ASSERT_TRUE(out.ok());
  EXPECT_THAT(*out, HasSubstr("uniform float4 gl_HalfPixel : register(c4);"));
}

TEST(Dx9Constants, APackedScalarIsRefusedNamingTheMember) {
  const std::string in =
      "cbuffer P : register(b0)\n{\n    float4 params_a : packoffset(c0);\n"
      "    float params_s : packoffset(c1.y);\n};\n";
  auto out = dx9_constants_as_registers(in);
  ASSERT_FALSE(out.ok());
  EXPECT_THAT(out.error().message, HasSubstr("params_s"));
  EXPECT_THAT(out.error().message, HasSubstr("float4 registers"));
}

TEST(Dx9Constants, TextWithoutConstantsIsUnchanged) {
  const std::string in = "float4 main() : COLOR0 { return 1.0.xxxx; }\n";
  auto out = dx9_constants_as_registers(in);
  ASSERT_TRUE(out.ok());
  EXPECT_EQ(*out, in);
}

}  // namespace
}  // namespace penumbra
