// Binding the text targets' shapes: the errors that name what a program in
// those shapes gets wrong.
#include <gtest/gtest.h>

#include <string>

#include "test_programs.hpp"
#include "text_programs.hpp"

namespace penumbra {
namespace {

const test::TestLight kLight;

class TextBindingTest : public test::EngineWithMapTest {
 protected:
  std::string query_error(const PassProgram& program, const ParamBlock& params) {
    const Error error = failed_query(program, params);
    if (error.message.empty()) return "";
    EXPECT_EQ(error.where, "query pass");
    return error.message;
  }

  std::string depth_error(const PassProgram& program) {
    auto result = engine_->render_depth(program, {}, 2, 2, params_);
    EXPECT_FALSE(result);
    return result ? "" : result.error().message;
  }

  ParamBlock params_ = test::make_params(kLight, 2, 2, 2, 2);
};

TEST_F(TextBindingTest, MissingMemberNamesItsParamBlockKey) {
  ParamBlock params = params_;
  params.erase("sampling");
  EXPECT_EQ(query_error(test::text_compare_program(test::TextShape::hlsl_dx9), params),
            "$Global member 'params_sampling' (ParamBlock key 'sampling') has no value in the "
            "ParamBlock (given: light, minmax_info, screen_size, shadow_map_size, source_size)");
}

TEST_F(TextBindingTest, StagesWhoseGlobalBlocksOverlapOnOneBindingAreRefused) {
  PassProgram program = test::text_compare_program(test::TextShape::hlsl_dx9);
  program.vert = test::reflected_stage("d3d9_fullscreen_b0.vert");
  EXPECT_EQ(query_error(program, params_),
            "$Global members 'gl_HalfPixel' and 'params_shadow_map_size' overlap at set 0 "
            "binding 0: the stages share that binding's buffer, so their blocks must agree (give "
            "each stage's block its own binding)");
}

TEST_F(TextBindingTest, SamplerNamedAfterNoImageIsRefused) {
  PassProgram program = test::text_compare_program(test::TextShape::hlsl_dx10_split);
  program.frag.iface.separate_samplers[2].name = "point_clamp";
  program.frag.iface.separate_samplers[2].image = paired_image_name("point_clamp");
  EXPECT_EQ(
      query_error(program, params_),
      "sampler 'point_clamp' (fragment stage) pairs with no image of the shader interface: "
      "a separate sampler is named _<image>_sampler after the image it samples "
      "(SPIRV-Cross's HLSL naming); allowed names: _shadow_depth_sampler, "
      "_shadow_cmp_sampler, _receivers_sampler, _shadow_minmax_sampler, _minmax_source_sampler, "
      "_screen_factor_sampler, _scene_colour_sampler");
}

TEST_F(TextBindingTest, OnlyShadowCmpsSamplerMayCompare) {
  PassProgram program = test::text_compare_program(test::TextShape::hlsl_dx10);
  program.frag.iface.separate_samplers[0].comparison = true;  // _shadow_depth_sampler
  EXPECT_EQ(query_error(program, params_),
            "sampler '_shadow_depth_sampler' (fragment stage) samples a depth image for "
            "comparisons; only shadow_cmp's sampler, _shadow_cmp_sampler, is a comparison sampler");
}

TEST_F(TextBindingTest, UnknownSeparateImageIsNamedWithTheAllowedNames) {
  PassProgram program = test::text_compare_program(test::TextShape::hlsl_dx10);
  program.frag.iface.separate_images[0].name = "shadow_mapp";
  EXPECT_EQ(query_error(program, params_),
            "image 'shadow_mapp' (fragment stage) is not part of the shader interface; allowed "
            "names: shadow_depth, shadow_cmp, receivers, shadow_minmax, minmax_source, "
            "screen_factor, scene_colour");
}

TEST_F(TextBindingTest, ImageAndAnotherImagesSamplerCannotShareABinding) {
  PassProgram program = test::text_compare_program(test::TextShape::hlsl_dx10);
  program.frag.iface.separate_samplers[2].binding = 2;  // _receivers_sampler onto shadow_cmp's
  EXPECT_EQ(query_error(program, params_),
            "'shadow_cmp' and '_receivers_sampler' share set 0 binding 2");
}

TEST_F(TextBindingTest, Dx9PositionSemanticWithoutBuiltinIsRefused) {
  PassProgram program = test::text_depth_program(test::TextShape::hlsl_dx9);
  program.vert = test::reflected_stage("d3d9_depth_position.vert");
  EXPECT_EQ(depth_error(program),
            "the vertex shader writes no clip-space position (BuiltIn Position: GLSL gl_Position, "
            "HLSL SV_Position)");
}

TEST_F(TextBindingTest, Dx9DepthSemanticWithoutBuiltinIsRefused) {
  PassProgram program = test::text_depth_program(test::TextShape::hlsl_dx9);
  program.frag = test::reflected_stage("d3d9_depth_depth.frag");
  EXPECT_EQ(depth_error(program),
            "fragment output '@entryPointOutput.depth' at location 1 has no attachment; the depth "
            "pass has one R32_SFLOAT target, at location 0");
}

// The query pass's target is R32G32_SFLOAT: (visibility, texel reads).
TEST_F(TextBindingTest, QueryOutputElsewhereNamesTheQueryTarget) {
  PassProgram program = test::text_compare_program(test::TextShape::hlsl_dx10);
  program.frag.iface.outputs[0].location = 1;
  EXPECT_EQ(query_error(program, params_),
            "fragment output '" + program.frag.iface.outputs[0].name +
                "' at location 1 has no attachment; the query pass has one R32G32_SFLOAT target, "
                "at location 0");
}

TEST_F(TextBindingTest, QueryOutputNeedsBothChannelsOfItsTarget) {
  PassProgram program = test::text_compare_program(test::TextShape::hlsl_dx9);
  program.frag.iface.outputs[0].components = 1;
  EXPECT_EQ(query_error(program, params_),
            "fragment output '" + program.frag.iface.outputs[0].name +
                "' has 1 component(s); the query pass's R32G32_SFLOAT target takes 2");
}

TEST_F(TextBindingTest, DepthPassNeedsTheFragmentDepth) {
  PassProgram program = test::text_depth_program(test::TextShape::hlsl_dx10);
  program.frag.iface.builtin_outputs.clear();
  EXPECT_EQ(depth_error(program),
            "the fragment shader writes no fragment depth (BuiltIn FragDepth: GLSL gl_FragDepth, "
            "HLSL SV_Depth); the depth pass stores the same normalized depth in the map's depth "
            "image as in output 0");
}

}  // namespace
}  // namespace penumbra
