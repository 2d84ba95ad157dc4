// Binding by reflection with the tests' SPIR-V programs: what the record
// and the module must agree on, and the errors naming what is wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "test_programs.hpp"

namespace penumbra {
namespace {

const test::TestLight kLight;

class BindingTest : public test::EngineWithMapTest {
 protected:
  ParamBlock params_ = test::make_params(kLight, 2, 2, 2, 2);
};

TextureBinding& frag_texture(PassProgram& program, const std::string& name) {
  auto& textures = program.reflection.frag.textures;
  return *std::find_if(textures.begin(), textures.end(),
                       [&](const TextureBinding& t) { return t.name == name; });
}

TEST_F(BindingTest, MissingParamBlockMemberIsNamed) {
  params_.erase("sampling");
  const Error error = failed_query(test::compare_program(), params_);
  EXPECT_EQ(error.kind, Error::Kind::bad_input);
  EXPECT_EQ(error.where, "query pass");
  EXPECT_EQ(error.message,
            "'sampling' has no value in the ParamBlock (given: light, minmax_info, screen_size, "
            "shadow_map_size, source_size)");
}

TEST_F(BindingTest, ExtraParamBlockEntriesAreIgnored) {
  params_["not_a_member"] = {1, 2, 3, 4};
  EXPECT_TRUE(engine_->run_query(test::compare_program(), *map_, FloatImage(2, 2, 3), params_));
}

TEST_F(BindingTest, ASamplerTheRecordLacksIsNamed) {
  const Error error = failed_query(test::unknown_sampler_program(), params_);
  EXPECT_EQ(error.where, "query pass");
  EXPECT_EQ(error.message,
            "the text declares sampler 'shadow_mapp' (set 0 binding 7) (fragment stage) that "
            "index.json's reflection lacks");
}

TEST_F(BindingTest, ATextureTheModuleLacksIsNamed) {
  PassProgram program = test::compare_program();
  frag_texture(program, "shadow_cmp").binding = 6;
  const Error error = failed_query(program, params_);
  EXPECT_EQ(error.message,
            "index.json's reflection names texture 'shadow_cmp' at set 0 binding 6 (fragment "
            "stage), which the text does not declare");
}

TEST_F(BindingTest, ATextureOutsideTheContractIsNamed) {
  PassProgram program = test::compare_program();
  frag_texture(program, "shadow_cmp").name = "shadow_mapp";
  const Error error = failed_query(program, params_);
  EXPECT_EQ(error.message,
            "index.json's reflection names texture 'shadow_mapp' (fragment stage), which is not a "
            "texture of the shader contract");
}

TEST_F(BindingTest, ASamplerStateWithoutTheComparisonIsRefused) {
  PassProgram program = test::compare_program();
  frag_texture(program, "shadow_cmp").sampler.state.comparison = false;
  const Error error = failed_query(program, params_);
  EXPECT_EQ(error.message,
            "texture 'shadow_cmp': the text samples it with comparisons (sampler 'shadow_cmp' (set "
            "0 binding 2), fragment stage), but index.json's reflection gives it a sampler without "
            "comparison");
}

TEST_F(BindingTest, TheFormatPicksTheMapsImage) {
  PassProgram program = test::point_program();
  frag_texture(program, "shadow_depth").format = "VK_FORMAT_R32G32_SFLOAT";
  const Error error = failed_query(program, params_);
  EXPECT_EQ(error.message,
            "'shadow_depth' is VK_FORMAT_R32G32_SFLOAT in index.json's reflection; the query pass "
            "has it as VK_FORMAT_D32_SFLOAT, VK_FORMAT_R32_SFLOAT");
}

TEST_F(BindingTest, TheDepthPassBindsOnlyShadowParams) {
  PassProgram program = test::depth_program();
  program.frag.iface.sampled_images.push_back({"receivers", 0, 3, false});
  PassProgram query = test::compare_program();
  program.reflection.frag.textures.push_back(frag_texture(query, "receivers"));
  auto map = engine_->render_depth(program, {}, 2, 2, params_);
  ASSERT_FALSE(map);
  EXPECT_EQ(map.error().where, "depth pass");
  EXPECT_EQ(map.error().message,
            "'receivers' has nothing to bind to in the depth pass, which binds: ShadowParams");
}

TEST_F(BindingTest, VertexInputMustMatchThePass) {
  PassProgram program = test::compare_program();
  program.vert.iface.inputs[0].components = 3;
  const Error error = failed_query(program, params_);
  EXPECT_EQ(error.message,
            "vertex input 'position' has 3 components; the query pass supplies position (2 "
            "floats) at location 0");
}

TEST(ParamBlockKeyTest, MembersReadTheKeyWithoutTheInstancePrefix) {
  EXPECT_EQ(param_block_key("light"), "light");         // ShadowParams block member
  EXPECT_EQ(param_block_key("params.light"), "light");  // struct in gl_DefaultUniformBlock
  EXPECT_EQ(param_block_key("params_screen_size"), "screen_size");  // SPIRV-Cross HLSL
  EXPECT_EQ(param_block_key("gl_HalfPixel"), "gl_HalfPixel");
  EXPECT_EQ(param_block_key("params"), "params");
  EXPECT_EQ(param_block_key("params_"), "params_");
  EXPECT_EQ(param_block_key("paramslight"), "paramslight");
  EXPECT_EQ(param_block_key("other.light"), "other.light");
}

TEST_F(BindingTest, NonSpirvIsRefused) {
  PassProgram program = test::compare_program();
  program.frag.spirv = {1, 2, 3, 4, 5, 6};
  const Error error = failed_query(program, params_);
  EXPECT_EQ(error.where, "query pass fragment shader");
  EXPECT_NE(error.message.find("is not a SPIR-V module"), std::string::npos);
}

}  // namespace
}  // namespace penumbra
