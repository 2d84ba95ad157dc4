// Each front-end shim rewrites exactly what it documents and nothing else,
// and the shim table applies each to its own target only.
#include "frontends/shims.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "default_library.hpp"
#include "emitted_texts.hpp"
#include "glslang_ast.hpp"
#include "penumbra/model/shader_contract.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::IsEmpty;

// The number of times `what` occurs in `text`.
std::size_t count(std::string_view text, std::string_view what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string_view::npos;
       at = text.find(what, at + 1)) {
    ++n;
  }
  return n;
}

TEST(EsslVersionShim, ChangesTheVersionLineOnly) {
  const std::string rest = "precision highp float;\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
  auto out = essl300_version_as_310("#version 300 es\n" + rest);
  ASSERT_TRUE(out.ok());
  EXPECT_EQ(*out, "#version 310 es\n" + rest);
}

TEST(EsslVersionShim, RefusesTextThatDoesNotBeginWithEssl300) {
  for (const char* text : {"#version 310 es\nvoid main() {}\n", "// x\n#version 300 es\n",
                           "#version 300\nvoid main() {}\n"}) {
    auto out = essl300_version_as_310(text);
    ASSERT_FALSE(out.ok()) << text;
    EXPECT_THAT(out.error().message, HasSubstr("#version 300 es"));
  }
}

// The meaning argument, checked: for every emitted ESSL 3.00 file, glslang's
// AST (types, precisions, operations) is the same read as 3.00 and as 3.10.
TEST(EsslVersionShim, LeavesGlslangsAstOfEveryEmittedTextUnchanged) {
  int checked = 0;
  int expected = 0;
  for (const Variant& variant : default_variants()) {
    // Two stages of each pass the technique lists: depth and query, and the
    // min-max build passes, screen_blur's blur_h, blur_v and composite, or
    // the deferred pass.
    expected += 2 * static_cast<int>(describe(variant.technique).passes.size());
    for (const EmittedStage& emitted : emitted_stages(variant, Target::essl300)) {
      const std::string& text = emitted.compiled.text;
      auto shimmed = essl300_version_as_310(text);
      ASSERT_TRUE(shimmed.ok()) << emitted.name;
      const std::string before = glslang_es_ast(text, emitted.stage);
      ASSERT_THAT(before, HasSubstr("Function Definition: main(")) << emitted.name;
      EXPECT_EQ(glslang_es_ast(*shimmed, emitted.stage), before) << emitted.name;
      ++checked;
    }
  }
  EXPECT_EQ(checked, expected);
}

constexpr std::string_view kDx9Vertex =
    "struct SPIRV_Cross_Input\n{\n    float4 position : POSITION;\n};\n\n"
    "struct SPIRV_Cross_Output\n{\n    float2 uv : TEXCOORD0;\n    float4 gl_Position : "
    "POSITION;\n};\n"
    "static float4 DEPTH_POSITION;\n";

TEST(Dx9SemanticsShim, RenamesPositionInTheOutputStructOnly) {
  auto out = dx9_output_semantics_as_system_values(kDx9Vertex);
  ASSERT_TRUE(out.ok());
  EXPECT_EQ(*out,
            "struct SPIRV_Cross_Input\n{\n    float4 position : POSITION;\n};\n\n"
            "struct SPIRV_Cross_Output\n{\n    float2 uv : TEXCOORD0;\n"
            "    float4 gl_Position : SV_Position;\n};\n"
            "static float4 DEPTH_POSITION;\n");
}

TEST(Dx9SemanticsShim, RenamesDepthAndKeepsColor) {
  const std::string in =
      "struct SPIRV_Cross_Output\n{\n    float4 c : COLOR0;\n    float gl_FragDepth : DEPTH;\n};\n";
  auto out = dx9_output_semantics_as_system_values(in);
  ASSERT_TRUE(out.ok());
  EXPECT_EQ(*out,
            "struct SPIRV_Cross_Output\n{\n    float4 c : COLOR0;\n"
            "    float gl_FragDepth : SV_Depth;\n};\n");
}

TEST(Dx9SemanticsShim, LeavesTextWithoutAnOutputStructUnchanged) {
  const std::string in = "float4 main() : COLOR0 { return 1.0.xxxx; }\n";
  auto out = dx9_output_semantics_as_system_values(in);
  ASSERT_TRUE(out.ok());
  EXPECT_EQ(*out, in);
}

// On emitted files (backprojection: the depth, min-max and query passes):
// exactly one semantic changes per stage, the position of vertex shaders and
// the depth of the depth pass's fragment shader.
TEST(Dx9SemanticsShim, ChangesOneSemanticOfEachEmittedEntryPoint) {
  const Variant* variant = find_default_variant("backprojection");
  ASSERT_NE(variant, nullptr);
  for (const EmittedStage& emitted : emitted_stages(*variant, Target::hlsl_dx9)) {
    const std::string& text = emitted.compiled.text;
    auto out = dx9_output_semantics_as_system_values(text);
    ASSERT_TRUE(out.ok()) << emitted.name;
    const bool renames = emitted.stage == ShaderStage::vertex || emitted.pass == PassKind::depth;
    const std::string_view to = emitted.stage == ShaderStage::vertex ? "SV_Position" : "SV_Depth";
    EXPECT_EQ(count(*out, to), renames ? 1u : 0u) << emitted.name;
    EXPECT_EQ(out->size() - text.size(), renames ? 3u : 0u) << emitted.name;  // "SV_" added
    EXPECT_EQ(count(*out, "SV_"), count(text, "SV_") + (renames ? 1 : 0)) << emitted.name;
  }
}

TEST(ShimTable, AppliesEachShimToItsTargetOnly) {
  const std::string essl = "#version 300 es\nvoid main() {}\n";
  const std::string dx9(kDx9Vertex);
  for (Target target : text_targets()) {
    SCOPED_TRACE(to_string(target));
    const std::string& text = target == Target::essl300 ? essl : dx9;
    auto out = apply_shims(target, text);
    ASSERT_TRUE(out.ok());
    std::vector<std::string> expected;
    if (target == Target::essl300) expected = {"essl300-version-310"};
    if (target == Target::hlsl_dx9) expected = {"dx9-output-semantics-as-sv"};
    EXPECT_EQ(out->shims, expected);
    EXPECT_EQ(out->text == text, expected.empty());
  }
}

TEST(ShimTable, NamesOnlyTheShimsThatChangedTheText) {
  auto out = apply_shims(Target::hlsl_dx9, "float4 main() : COLOR0 { return 1.0.xxxx; }\n");
  ASSERT_TRUE(out.ok());
  EXPECT_THAT(out->shims, IsEmpty());
}

}  // namespace
}  // namespace penumbra::testing
