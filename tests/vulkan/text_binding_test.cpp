// Binding each target's text by its reflection record: a record that names
// what the text lacks, or lacks what the text declares, is refused with the
// entry named; a sampler state the text cannot use is refused, and one it
// can changes what the pass computes.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "test_programs.hpp"
#include "text_programs.hpp"

namespace penumbra {
namespace {

const test::TestLight kLight;

// pcss reads shadow_depth, shadow_cmp (not on hlsl_dx9) and receivers.
constexpr const char* kVariant = "pcss_b16_p16_poisson";

class TextBindingTest : public ::testing::TestWithParam<Target> {
 protected:
  void SetUp() override {
    engine_ = test::make_engine();
    ASSERT_NE(engine_, nullptr);
    // A checkerboard of near and far texels: bilinear and point reads differ.
    FloatImage depth(8, 8, 1);
    for (int j = 0; j < 8; ++j) {
      for (int i = 0; i < 8; ++i) depth.at(i, j) = (i + j) % 2 == 0 ? 0.25f : 0.75f;
    }
    auto map = engine_->upload_shadow_map(depth);
    ASSERT_TRUE(map) << map.error().to_string();
    map_ = *map;
    program_ = test::text_program(kVariant, PassKind::query, GetParam());
  }

  Result<FloatImage> query(const PassProgram& program) {
    // Receivers between the near and far texels, off the texel centres.
    FloatImage receivers(8, 8, 3);
    for (int j = 0; j < 8; ++j) {
      for (int i = 0; i < 8; ++i) {
        receivers.at(i, j, 0) = (static_cast<float>(i) + 0.3f) / 8.0f;
        receivers.at(i, j, 1) = (static_cast<float>(j) + 0.6f) / 8.0f;
        receivers.at(i, j, 2) = 0.5f / kLight.depth_scale;
      }
    }
    return engine_->run_query(program, *map_, receivers, params_);
  }

  std::string error(const PassProgram& program) {
    auto result = query(program);
    EXPECT_FALSE(result);
    if (result) return "";
    EXPECT_EQ(result.error().kind, Error::Kind::bad_input);
    EXPECT_EQ(result.error().where, "query pass");
    return result.error().message;
  }

  TextureBinding* texture(const std::string& name) {
    auto& textures = program_.reflection.frag.textures;
    const auto it = std::find_if(textures.begin(), textures.end(),
                                 [&](const TextureBinding& t) { return t.name == name; });
    return it == textures.end() ? nullptr : &*it;
  }

  std::unique_ptr<Engine> engine_;
  std::shared_ptr<ShadowMap> map_;
  PassProgram program_;
  ParamBlock params_ = test::make_params(kLight, 8, 8, 8, 8);
};

TEST_P(TextBindingTest, TheRecordBindsTheText) {
  auto visibility = query(program_);
  EXPECT_TRUE(visibility) << visibility.error().to_string();
}

TEST_P(TextBindingTest, ADeclarationTheRecordLacksIsNamed) {
  auto& textures = program_.reflection.frag.textures;
  textures.erase(std::remove_if(textures.begin(), textures.end(),
                                [](const TextureBinding& t) { return t.name == "receivers"; }),
                 textures.end());
  const std::string message = error(program_);
  EXPECT_NE(message.find("the text declares"), std::string::npos) << message;
  EXPECT_NE(message.find("'receivers'"), std::string::npos) << message;
  EXPECT_NE(message.find("that index.json's reflection lacks"), std::string::npos) << message;
}

TEST_P(TextBindingTest, ATextureTheTextLacksIsNamed) {
  TextureBinding extra = *texture("receivers");
  extra.name = "scene_colour";  // a texture of shader_contract.hpp that no query pass reads
  extra.binding = extra.binding ? std::optional<std::uint32_t>(6) : std::nullopt;
  if (!extra.reg.empty()) extra.reg = extra.reg.substr(0, 1) + "6";
  if (!extra.sampler.reg.empty()) extra.sampler.reg = "s6";
  program_.reflection.frag.textures.push_back(extra);
  const std::string message = error(program_);
  EXPECT_NE(message.find("index.json's reflection names texture 'scene_colour'"), std::string::npos)
      << message;
  EXPECT_NE(message.find("which the text does not declare"), std::string::npos) << message;
}

TEST_P(TextBindingTest, AConstantTheTextLacksIsNamed) {
  ConstantBinding* constant = nullptr;
  auto& frag = program_.reflection.frag;
  if (!frag.uniforms.empty()) constant = &frag.uniforms.front();
  if (!frag.blocks.empty()) constant = &frag.blocks.front().members.front();
  ASSERT_NE(constant, nullptr);
  constant->name = "params.no_such_member";
  constant->reg = constant->reg.empty() ? "" : "c40";
  constant->offset = constant->offset ? std::optional<std::uint32_t>(640) : std::nullopt;
  const std::string message = error(program_);
  EXPECT_NE(message.find("'params.no_such_member'"), std::string::npos) << message;
}

TEST_P(TextBindingTest, AMissingParameterIsNamed) {
  params_.erase("sampling");
  const std::string message = error(program_);
  // spirv names the member as its parameter; the other targets add the parameter.
  EXPECT_NE(message.find("sampling'"), std::string::npos) << message;
  EXPECT_NE(message.find("has no value in the ParamBlock"), std::string::npos) << message;
}

TEST_P(TextBindingTest, AComparisonTheTextDoesNotMakeIsRefused) {
  TextureBinding* receivers = texture("receivers");
  ASSERT_NE(receivers, nullptr);
  receivers->sampler.state.comparison = true;
  EXPECT_NE(error(program_).find("texture 'receivers': the text samples it without comparisons"),
            std::string::npos);
}

TEST_P(TextBindingTest, TheRecordsFilterIsTheSamplersFilter) {
  // hlsl_dx9 filters in the shader (point reads only): its state says nearest.
  TextureBinding* cmp = texture("shadow_cmp");
  if (!cmp) GTEST_SKIP() << to_string(GetParam()) << " has no shadow_cmp";
  auto linear = query(program_);
  ASSERT_TRUE(linear) << linear.error().to_string();
  cmp->sampler.state.filter = Filter::nearest;
  auto nearest = query(program_);
  ASSERT_TRUE(nearest) << nearest.error().to_string();
  EXPECT_NE(nearest->data, linear->data);
}

TEST_P(TextBindingTest, TheRenderTargetFormatMustBeThePasses) {
  program_.reflection.render_targets[0].format =
      std::string(api_format(GetParam(), TextureFormat::rgba32_float));
  EXPECT_NE(error(program_).find("index.json's reflection gives render target 'visibility' the "
                                 "format"),
            std::string::npos);
}

TEST_P(TextBindingTest, TheVertexInputMustBeThePasses) {
  program_.reflection.vertex_inputs[0].components = 3;
  EXPECT_EQ(error(program_),
            "index.json's reflection gives the vertex inputs position (3 floats); the query pass "
            "supplies position (2 floats) at location 0");
}

TEST_P(TextBindingTest, TheDepthPassNeedsTheFragmentDepth) {
  PassProgram program = test::text_program("hard", PassKind::depth, GetParam());
  program.frag.iface.builtin_outputs.clear();
  auto result = engine_->render_depth(program, {}, 2, 2, params_);
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().message,
            "the fragment shader writes no fragment depth (BuiltIn FragDepth: GLSL gl_FragDepth, "
            "HLSL SV_Depth); the depth pass stores the same normalized depth in the map's depth "
            "image as in output 0");
}

INSTANTIATE_TEST_SUITE_P(Targets, TextBindingTest, ::testing::ValuesIn(kAllTargets),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

}  // namespace
}  // namespace penumbra
