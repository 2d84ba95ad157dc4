// Every default variant's glsl330, glsl450 and essl300 reflection proved
// against Mesa's OpenGL driver (desktop 4.5 core for the GLSL targets,
// OpenGL ES 3.0 for essl300), and a corrupted entry reported.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "built_library.hpp"
#include "corrupted_reflection.hpp"
#include "default_library.hpp"
#include "egl_context.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

class InterfaceGlProof : public ::testing::TestWithParam<std::string> {};

TEST_P(InterfaceGlProof, MesaOpenGlFindsTheGlslReflection) {
  const Status proved =
      prove_default_variant(GetParam(), prove_mesa_gl, {Target::glsl330, Target::glsl450});
  EXPECT_TRUE(proved.ok()) << proved.error().to_string();
}

TEST_P(InterfaceGlProof, MesaOpenGlEsFindsTheEsslReflection) {
  if (auto es = EglContext::current(GlApi::es); !es) {
    GTEST_SKIP() << "no OpenGL ES 3.0 context: " << es.error().to_string();
  }
  const Status proved = prove_default_variant(GetParam(), prove_mesa_gl, {Target::essl300});
  EXPECT_TRUE(proved.ok()) << proved.error().to_string();
}

INSTANTIATE_TEST_SUITE_P(DefaultLibrary, InterfaceGlProof,
                         ::testing::ValuesIn(default_variant_names()),
                         [](const auto& param_info) { return test_name(param_info.param); });

TEST(CorruptedReflection, MesaOpenGlReportsAMisnamedUniform) {
  const std::string error =
      prove_corrupted(prove_mesa_gl, PassKind::depth, Target::glsl330,
                      [](PassReflection& r) { r.vert.uniforms.at(1).name = "params_light"; });
  EXPECT_THAT(error, HasSubstr("vert uniform params_light: in the reflection"));
  EXPECT_THAT(error, HasSubstr("vert uniform params.light: Mesa's OpenGL reports it"));
}

TEST(CorruptedReflection, MesaOpenGlReportsAMissingTexture) {
  const std::string error =
      prove_corrupted(prove_mesa_gl, PassKind::query, Target::glsl450,
                      [](PassReflection& r) { r.frag.textures.erase(r.frag.textures.begin()); });
  EXPECT_THAT(error, HasSubstr("frag texture shadow_depth: Mesa's OpenGL reports it"));
}

TEST(CorruptedReflection, MesaOpenGlReportsAWrongMemberOffset) {
  const std::string error =
      prove_corrupted(prove_mesa_gl, PassKind::query, Target::glsl450,
                      [](PassReflection& r) { r.frag.blocks.at(0).members.at(2).offset = 48; });
  EXPECT_THAT(error, HasSubstr("member ShadowParams.sampling: the reflection says 'vec4 at 48'"));
}

}  // namespace
}  // namespace penumbra::testing
