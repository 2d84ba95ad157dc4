// Counting Shader Model 3 instruction slots on vkd3d-compiler's assembly.
#include "targets/sm3_slots.hpp"

#include <gtest/gtest.h>

namespace penumbra {
namespace {

TEST(Sm3Slots, CountsInstructionsNotDeclarations) {
  const char* assembly =
      "ps_3_0\n"
      "dcl_texcoord0 v0\n"
      "def c6 = 0.00000000e+00, 1.00000000e+00, 0.00000000e+00, 0.00000000e+00\n"
      "defi i0 = 255, 0, 0, 0\n"
      "dcl_2d s1\n"
      "mov r0.xyzw, c6.xyzw\n"
      "rep i0.xyzw\n"
      "    texldl r1.xyzw, r0.xyzw, s1\n"
      "    if_ne r1.x, -r1.x\n"
      "        break\n"
      "    endif\n"
      "endrep\n"
      "mov_sat oC0.xyzw, r1.xyzw\n";
  EXPECT_EQ(count_sm3_slots(assembly), 8);
}

TEST(Sm3Slots, MacrosCountTheirExpansion) {
  EXPECT_EQ(count_sm3_slots("ps_3_0\nnrm r0.xyz, r1\nsincos r2.xy, r0.x\npow r3.x, r0.x, r1.x\n"),
            3 + 8 + 3);
  EXPECT_EQ(count_sm3_slots("vs_3_0\nm4x4 o0, v0, c0\nlrp r0, r1, r2, r3\n"), 4 + 2);
}

TEST(Sm3Slots, EmptyAssemblyHasNoSlots) {
  EXPECT_EQ(count_sm3_slots(""), 0);
  EXPECT_EQ(count_sm3_slots("ps_3_0\n\n// comment\n"), 0);
}

}  // namespace
}  // namespace penumbra
