// A wrong register, binding, name or a missing entry in one reflection is
// reported by the SPIRV-Cross and glslang proofs, naming the entry.
#include "corrupted_reflection.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

TextureBinding& texture(StageBindings& stage, std::string_view name) {
  for (TextureBinding& t : stage.textures) {
    if (t.name == name) return t;
  }
  throw std::runtime_error("no texture " + std::string(name));
}

TEST(CorruptedReflection, SpirvCrossReportsAWrongBinding) {
  const std::string error =
      prove_corrupted(prove_spirv, PassKind::query, Target::spirv,
                      [](PassReflection& r) { texture(r.frag, "shadow_cmp").binding = 5; });
  EXPECT_THAT(error, HasSubstr("frag texture shadow_cmp: the reflection says 'set 0, binding 5"));
  EXPECT_THAT(error, HasSubstr("pcss_b16_p16_poisson, query pass, spirv"));
}

TEST(CorruptedReflection, SpirvCrossReportsAMissingTexture) {
  const std::string error = prove_corrupted(prove_spirv, PassKind::query, Target::spirv,
                                            [](PassReflection& r) { r.frag.textures.pop_back(); });
  EXPECT_THAT(error, HasSubstr("frag texture receivers: SPIRV-Cross reports it"));
}

TEST(CorruptedReflection, GlslangReportsAnEsslBindingTheTextLacks) {
  const std::string error =
      prove_corrupted(prove_glslang_essl, PassKind::query, Target::essl300,
                      [](PassReflection& r) { texture(r.frag, "shadow_cmp").binding = 2; });
  EXPECT_THAT(error, HasSubstr("frag texture shadow_cmp: the reflection says 'binding 2"));
}

TEST(CorruptedReflection, GlslangReportsAWrongDx10SamplerRegister) {
  const std::string error =
      prove_corrupted(prove_glslang_hlsl, PassKind::query, Target::hlsl_dx10,
                      [](PassReflection& r) { texture(r.frag, "shadow_cmp").sampler.reg = "s3"; });
  EXPECT_THAT(error, HasSubstr("frag sampler _shadow_cmp_sampler: the reflection says 's3"));
}

TEST(CorruptedReflection, GlslangReportsATextureRegisterOfTheWrongClass) {
  const std::string error =
      prove_corrupted(prove_glslang_hlsl, PassKind::query, Target::hlsl_dx10,
                      [](PassReflection& r) { texture(r.frag, "receivers").reg = "s3"; });
  EXPECT_THAT(error, HasSubstr("frag texture receivers: the reflection says 's3"));
}

TEST(CorruptedReflection, GlslangReportsAWrongDx9ConstantRegister) {
  const std::string error =
      prove_corrupted(prove_glslang_hlsl, PassKind::query, Target::hlsl_dx9,
                      [](PassReflection& r) { r.frag.uniforms.at(1).reg = "c2"; });
  EXPECT_THAT(error, HasSubstr("frag constant params_light: the reflection says 'c2"));
}

TEST(CorruptedReflection, GlslangReportsAMissingHalfPixelConstant) {
  const std::string error = prove_corrupted(prove_glslang_hlsl, PassKind::query, Target::hlsl_dx9,
                                            [](PassReflection& r) { r.vert.uniforms.clear(); });
  EXPECT_THAT(error, HasSubstr("vert constant gl_HalfPixel: glslang (HLSL) reports it (c6"));
}

}  // namespace
}  // namespace penumbra::testing
