// Every default variant's reflection in index.json proved against its
// emitted files by parsers that are not the generator: SPIR-V by
// SPIRV-Cross, ESSL 3.00 by glslang, every HLSL target by glslang's HLSL
// front end. The OpenGL driver's proofs are in interface_gl_proof_test.cpp.
#include <gtest/gtest.h>

#include "built_library.hpp"
#include "default_library.hpp"

namespace penumbra::testing {
namespace {

class InterfaceProof : public ::testing::TestWithParam<std::string> {};

TEST_P(InterfaceProof, SpirvCrossFindsTheSpirvReflection) {
  const Status proved = prove_default_variant(GetParam(), prove_spirv, {Target::spirv});
  EXPECT_TRUE(proved.ok()) << proved.error().to_string();
}

TEST_P(InterfaceProof, GlslangFindsTheEsslReflection) {
  const Status proved = prove_default_variant(GetParam(), prove_glslang_essl, {Target::essl300});
  EXPECT_TRUE(proved.ok()) << proved.error().to_string();
}

TEST_P(InterfaceProof, GlslangFindsTheHlslReflection) {
  const Status proved = prove_default_variant(GetParam(), prove_glslang_hlsl, hlsl_targets());
  EXPECT_TRUE(proved.ok()) << proved.error().to_string();
}

INSTANTIATE_TEST_SUITE_P(DefaultLibrary, InterfaceProof,
                         ::testing::ValuesIn(default_variant_names()),
                         [](const auto& param_info) { return test_name(param_info.param); });

}  // namespace
}  // namespace penumbra::testing
