// Binding by reflection: what a program may declare, and the errors naming
// what is wrong when it declares something else.
#include <gtest/gtest.h>

#include <string>

#include "test_programs.hpp"

namespace penumbra {
namespace {

const test::TestLight kLight;

class BindingTest : public test::EngineWithMapTest {};

TEST_F(BindingTest, MissingParamBlockMemberIsNamed) {
  ParamBlock params = test::make_params(kLight, 2, 2, 2, 2);
  params.erase("sampling");
  const Error error = failed_query(test::compare_program(), params);
  EXPECT_EQ(error.kind, Error::Kind::bad_input);
  EXPECT_EQ(error.where, "query pass");
  EXPECT_EQ(error.message,
            "ShadowParams member 'sampling' has no value in the ParamBlock (given: light, "
            "minmax_info, screen_size, shadow_map_size, source_size)");
}

TEST_F(BindingTest, ExtraParamBlockEntriesAreIgnored) {
  ParamBlock params = test::make_params(kLight, 2, 2, 2, 2);
  params["not_a_member"] = {1, 2, 3, 4};
  EXPECT_TRUE(engine_->run_query(test::compare_program(), *map_, FloatImage(2, 2, 3), params));
}

TEST_F(BindingTest, UnknownSamplerIsNamedWithTheAllowedNames) {
  const Error error =
      failed_query(test::unknown_sampler_program(), test::make_params(kLight, 2, 2, 2, 2));
  EXPECT_EQ(error.kind, Error::Kind::bad_input);
  EXPECT_EQ(error.where, "query pass");
  EXPECT_EQ(error.message,
            "sampler 'shadow_mapp' (fragment stage) is not part of the shader interface; allowed "
            "names: shadow_depth, shadow_cmp, receivers, shadow_minmax, minmax_source, "
            "screen_factor, scene_colour");
}

TEST_F(BindingTest, UnknownUniformBlockIsNamed) {
  PassProgram program = test::compare_program();
  program.frag.iface.uniform_blocks[0].type_name = "Globals";
  const Error error = failed_query(program, test::make_params(kLight, 2, 2, 2, 2));
  EXPECT_NE(error.message.find("uniform block 'Globals'"), std::string::npos) << error.message;
}

TEST_F(BindingTest, SamplerOfTheWrongKindIsNamed) {
  PassProgram program = test::compare_program();
  program.frag.iface.sampled_images[1].comparison = false;  // shadow_cmp as a plain sampler2D
  const Error error = failed_query(program, test::make_params(kLight, 2, 2, 2, 2));
  EXPECT_EQ(error.message, "sampler 'shadow_cmp' must be a sampler2DShadow (comparison sampler)");
}

TEST_F(BindingTest, TwoResourcesOnOneBindingAreNamed) {
  PassProgram program = test::compare_program();
  program.frag.iface.sampled_images[1].binding = 1;  // shadow_cmp onto shadow_depth's binding
  const Error error = failed_query(program, test::make_params(kLight, 2, 2, 2, 2));
  EXPECT_EQ(error.message, "'shadow_depth' and 'shadow_cmp' share set 0 binding 1");
}

TEST_F(BindingTest, TheDepthPassBindsOnlyShadowParams) {
  PassProgram program = test::depth_program();
  program.frag.iface.sampled_images.push_back({"receivers", 0, 3, false});
  auto map = engine_->render_depth(program, {}, 2, 2, test::make_params(kLight, 2, 2, 2, 2));
  ASSERT_FALSE(map);
  EXPECT_EQ(map.error().where, "depth pass");
  EXPECT_EQ(map.error().message,
            "'receivers' has nothing to bind to in the depth pass, which binds: ShadowParams");
}

TEST_F(BindingTest, VertexInputMustMatchThePass) {
  PassProgram program = test::compare_program();
  program.vert.iface.inputs[0].components = 3;
  const Error error = failed_query(program, test::make_params(kLight, 2, 2, 2, 2));
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
  const Error error = failed_query(program, test::make_params(kLight, 2, 2, 2, 2));
  EXPECT_EQ(error.where, "query pass fragment shader");
  EXPECT_NE(error.message.find("is not a SPIR-V module"), std::string::npos);
}

}  // namespace
}  // namespace penumbra
