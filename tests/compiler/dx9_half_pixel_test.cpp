// The hlsl_dx9 half-pixel shim turns the y term of SPIRV-Cross's fixup, and
// only that, and refuses a fixup it does not know.
#include "targets/dx9_half_pixel.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace penumbra {
namespace {

using ::testing::HasSubstr;

const std::string kFixup =
    "    gl_Position.x = gl_Position.x - gl_HalfPixel.x * gl_Position.w;\n"
    "    gl_Position.y = gl_Position.y + gl_HalfPixel.y * gl_Position.w;\n"
    "    gl_Position.y = -gl_Position.y;\n";

TEST(Dx9HalfPixel, TurnsTheYTermBeforeTheFlip) {
  auto out = dx9_half_pixel_after_flip("uniform float4 gl_HalfPixel : register(c6);\n" + kFixup);
  ASSERT_TRUE(out.ok());
  EXPECT_EQ(*out,
            "uniform float4 gl_HalfPixel : register(c6);\n"
            "    gl_Position.x = gl_Position.x - gl_HalfPixel.x * gl_Position.w;\n"
            "    gl_Position.y = gl_Position.y - gl_HalfPixel.y * gl_Position.w;\n"
            "    gl_Position.y = -gl_Position.y;\n");
}

TEST(Dx9HalfPixel, PixelShadersPassUnchanged) {
  const std::string pixel = "float4 main() : COLOR0 { return 0.0f.xxxx; }\n";
  auto out = dx9_half_pixel_after_flip(pixel);
  ASSERT_TRUE(out.ok());
  EXPECT_EQ(*out, pixel);
}

TEST(Dx9HalfPixel, AnUnknownFixupIsRefused) {
  auto without_flip = dx9_half_pixel_after_flip(
      "uniform float4 gl_HalfPixel;\n"
      "    gl_Position.y = gl_Position.y + gl_HalfPixel.y * gl_Position.w;\n");
  ASSERT_FALSE(without_flip.ok());
  EXPECT_THAT(without_flip.error().message, HasSubstr("half-pixel shim cannot apply"));
  auto other = dx9_half_pixel_after_flip("uniform float4 gl_HalfPixel;\n    gl_Position.y += 1;\n");
  EXPECT_FALSE(other.ok());
}

}  // namespace
}  // namespace penumbra
