// What run_query reports when the GLSL, its reflection or the inputs are
// wrong: compile and link logs, a program and a reflection that disagree,
// missing parameters, unusable images; and that the reflection, not the
// text, decides what is bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <span>
#include <string>

#include "default_library.hpp"
#include "gl_fixture.hpp"

namespace penumbra::testing {
namespace {

// `text` with the first `from` replaced by `to`; fails the test if absent.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "'" << from << "' not in the emitted text";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The fragment stage's texture `name` in `reflection`; fails the test if absent.
TextureBinding* reflected_texture(PassReflection& reflection, const std::string& name) {
  auto& textures = reflection.frag.textures;
  const auto found = std::find_if(textures.begin(), textures.end(),
                                  [&](const TextureBinding& t) { return t.name == name; });
  EXPECT_NE(found, textures.end()) << "no texture '" << name << "' in the reflection";
  return found == textures.end() ? nullptr : &*found;
}

// The fragment stage's constant carrying `parameter`: a loose uniform
// (glsl330) or a member of the ShadowParams block (glsl450).
std::vector<ConstantBinding>& constants(PassReflection& reflection) {
  return reflection.frag.blocks.empty() ? reflection.frag.uniforms
                                        : reflection.frag.blocks.front().members;
}

class GlErrors : public ::testing::TestWithParam<Target> {
 protected:
  void SetUp() override {
    engine_ = make_gl_engine();
    ASSERT_NE(engine_, nullptr);
    auto variant = find_default_variant("pcss_b16_p16_whitepaper16");
    ASSERT_NE(variant, nullptr);
    auto text = emitted_pass(*variant, GetParam(), PassKind::query);
    ASSERT_TRUE(text.ok()) << text.error().to_string();
    text_ = std::move(*text);
    inputs_ = any_scene_inputs();
  }

  Result<GlQueryOutput> run(const PassText& pass, const ParamBlock& params) {
    return engine_->run_query({pass.view()}, inputs_.normalized_depth, inputs_.receivers, params);
  }
  Result<GlQueryOutput> run(const PassText& pass) { return run(pass, inputs_.params); }
  // The pass with other texts and the emitted reflection.
  Result<GlQueryOutput> run(const std::string& vert, const std::string& frag) {
    return run(PassText{vert, frag, text_.reflection});
  }
  // The emitted texts with another reflection.
  Result<GlQueryOutput> run(const PassReflection& reflection) {
    return run(PassText{text_.vert, text_.frag, reflection});
  }

  // Expects `result` to fail with `kind` and a message containing `part`.
  static void expect_error(const Result<GlQueryOutput>& result, Error::Kind kind,
                           const std::string& where, const std::string& part) {
    ASSERT_FALSE(result.ok()) << "expected an error mentioning " << part;
    EXPECT_EQ(result.error().kind, kind) << result.error().to_string();
    EXPECT_EQ(result.error().where, where) << result.error().to_string();
    EXPECT_NE(result.error().message.find(part), std::string::npos) << result.error().to_string();
  }

  std::unique_ptr<GlEngine> engine_;
  PassText text_;
  SceneInputs inputs_;
};

TEST_P(GlErrors, ValidPassRunsAfterFailures) {
  expect_error(run(text_.vert, replaced(text_.frag, "vec3 query = textureLod(receivers",
                                        "oops; vec3 query = textureLod(receivers")),
               Error::Kind::compile, "query pass", "oops");
  auto visibility = run(text_);
  ASSERT_TRUE(visibility.ok()) << visibility.error().to_string();
  EXPECT_EQ(visibility->visibility.width, inputs_.receivers.width);
  EXPECT_EQ(visibility->visibility.height, inputs_.receivers.height);
}

TEST_P(GlErrors, CompileErrorsCarryTheDriversLog) {
  // Mesa's logs read "0:LINE(COLUMN): error: ...".
  expect_error(run(replaced(text_.vert, "gl_Position =", "gl_Positio ="), text_.frag),
               Error::Kind::compile, "query pass", "vertex stage: the GL driver's compiler");
  expect_error(run(text_.vert, replaced(text_.frag, "float sum = 0.0;", "float sum = 0.0")),
               Error::Kind::compile, "query pass", "fragment stage: the GL driver's compiler");
}

TEST_P(GlErrors, LinkErrorsCarryTheDriversLog) {
  // Each stage compiles; only together do their screen_uv types disagree.
  const std::string vert =
      replaced(replaced(text_.vert, "out vec2 screen_uv;", "out vec3 screen_uv;"),
               "screen_uv = (position * 0.5) + vec2(0.5);",
               "screen_uv = vec3((position * 0.5) + vec2(0.5), 0.0);");
  expect_error(run(vert, text_.frag), Error::Kind::compile, "query pass", "screen_uv");
}

// Whatever the program reports active must be in the reflection, named
// there as GL names it.
TEST_P(GlErrors, ActiveNamesMissingFromTheReflectionAreRejected) {
  const std::string renamed =
      replaced(replaced(text_.frag, "sampler2D receivers;", "sampler2D receiverz;"),
               "textureLod(receivers,", "textureLod(receiverz,");
  expect_error(run(text_.vert, renamed), Error::Kind::bad_input, "query pass",
               "uniform 'receiverz' is active in the program but not in the reflection");
  const std::string extra =
      replaced(replaced(text_.frag, "void main()", "uniform float exposure;\nvoid main()"),
               "visibility = vec4(visible,", "visibility = vec4(visible * exposure,");
  expect_error(run(text_.vert, extra), Error::Kind::bad_input, "query pass",
               "uniform 'exposure' is active in the program but not in the reflection");
  const std::string output =
      replaced(replaced(text_.frag, "out vec4 visibility;", "out vec4 shadowing;"),
               "visibility = vec4(", "shadowing = vec4(");
  expect_error(run(text_.vert, output), Error::Kind::bad_input, "query pass",
               "fragment output 'shadowing' is active in the program but not in the reflection");

  // The emitted text against a reflection that lost one of its names.
  PassReflection no_receivers = text_.reflection;
  std::erase_if(no_receivers.frag.textures,
                [](const TextureBinding& t) { return t.name == "receivers"; });
  expect_error(run(no_receivers), Error::Kind::bad_input, "query pass",
               "uniform 'receivers' is active in the program but not in the reflection");
  if (text_.reflection.frag.blocks.empty()) return;
  // glsl450: a member of the ShadowParams block. (glsl330's struct members
  // cannot be told from the unread ones GL reports too: docs/gl.md.)
  PassReflection no_sampling = text_.reflection;
  auto& members = no_sampling.frag.blocks.front().members;
  std::erase_if(members, [](const ConstantBinding& c) { return c.parameter == "sampling"; });
  expect_error(run(no_sampling), Error::Kind::bad_input, "query pass",
               "uniform 'ShadowParams.sampling' is active in the program but not in the "
               "reflection");
}

// GL drops inactive uniforms: a reflection name the program does not know
// binds nothing and changes nothing.
TEST_P(GlErrors, ReflectionNamesTheProgramLacksAreSkipped) {
  auto expected = run(text_);
  ASSERT_TRUE(expected.ok()) << expected.error().to_string();
  PassReflection extra = text_.reflection;
  ConstantBinding unused = constants(extra).front();
  unused.name += "_unused";
  constants(extra).push_back(unused);
  TextureBinding minmax = *reflected_texture(extra, "receivers");
  minmax.name = "shadow_minmax";
  if (minmax.binding) minmax.binding = 4;
  extra.frag.textures.push_back(minmax);
  auto visibility = run(extra);
  ASSERT_TRUE(visibility.ok()) << visibility.error().to_string();
  EXPECT_EQ(visibility->visibility.data, expected->visibility.data);
}

// The sampler objects come from the reflection's sampler state: shadow_cmp
// with point comparisons instead of bilinear ones renders another image.
TEST_P(GlErrors, SamplerStateComesFromTheReflection) {
  auto expected = run(text_);
  ASSERT_TRUE(expected.ok()) << expected.error().to_string();
  PassReflection point = text_.reflection;
  TextureBinding* cmp = reflected_texture(point, "shadow_cmp");
  ASSERT_NE(cmp, nullptr);
  ASSERT_EQ(cmp->sampler.state.filter, Filter::linear);
  cmp->sampler.state.filter = Filter::nearest;
  auto visibility = run(point);
  ASSERT_TRUE(visibility.ok()) << visibility.error().to_string();
  EXPECT_NE(visibility->visibility.data, expected->visibility.data);
}

TEST_P(GlErrors, FormatsComeFromTheReflection) {
  PassReflection r32f = text_.reflection;
  TextureBinding* receivers = reflected_texture(r32f, "receivers");
  ASSERT_NE(receivers, nullptr);
  receivers->format = "GL_R32F";  // too few channels for (u, v, z_r)
  expect_error(run(r32f), Error::Kind::bad_input, "query pass",
               "texture 'receivers' has 3 channels; its format GL_R32F holds 1");
  PassReflection unknown = text_.reflection;
  unknown.render_targets.front().format = "GL_RGBA8";
  expect_error(run(unknown), Error::Kind::bad_input, "query pass",
               "render target 'visibility' has format 'GL_RGBA8', which the GL engine does not "
               "create");
}

TEST_P(GlErrors, MissingParameterIsNamed) {
  ParamBlock params = inputs_.params;
  params.erase("sampling");
  expect_error(run(text_, params), Error::Kind::bad_input, "query pass",
               "ShadowParams member 'sampling' (uniform '");
}

TEST_P(GlErrors, UnusableImagesAreRejected) {
  FloatImage depth = inputs_.normalized_depth;
  depth.at(3, 2) = 1.5f;
  expect_error(engine_->run_query({text_.view()}, depth, inputs_.receivers, inputs_.params),
               Error::Kind::bad_input, "shadow map", "texel (3, 2)");
  const FloatImage two_channels(4, 4, 2);
  expect_error(
      engine_->run_query({text_.view()}, inputs_.normalized_depth, two_channels, inputs_.params),
      Error::Kind::bad_input, "receivers", "3 or 4 channels");
}

// run_surface draws an engine's geometry: three floats per vertex, whole
// triangles. The query pass's full-screen program is no such thing.
TEST_P(GlErrors, SurfacesNeedWholeTrianglesOfThreeFloats) {
  const std::vector<std::array<float, 3>> triangle = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  const auto surface = [&](std::span<const std::array<float, 3>> vertices) {
    return engine_->run_surface(text_.view(), vertices, inputs_.normalized_depth, 8, 8,
                                inputs_.params);
  };
  const auto fails = [](const Result<FloatImage>& result, const std::string& part) {
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().kind, Error::Kind::bad_input) << result.error().to_string();
    EXPECT_EQ(result.error().where, "surface pass") << result.error().to_string();
    EXPECT_NE(result.error().message.find(part), std::string::npos) << result.error().to_string();
  };
  fails(surface(std::span(triangle).first(2)), "not a whole number of triangles");
  fails(surface(triangle), "with 3 GL_FLOAT components per vertex");
}

INSTANTIATE_TEST_SUITE_P(Emitted, GlErrors, ::testing::Values(Target::glsl330, Target::glsl450),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

using GlExplicitBindings = GlErrors;

// GLSL 4.50's units and block binding are the reflection's; the engine
// binds there and refuses a program that declares others.
TEST_P(GlExplicitBindings, BindingsComeFromTheReflection) {
  auto expected = run(text_);
  ASSERT_TRUE(expected.ok()) << expected.error().to_string();
  const std::string moved = replaced(
      replaced(text_.frag, "binding = 3) uniform sampler2D receivers",
               "binding = 7) uniform sampler2D receivers"),
      "binding = 0, std140) uniform ShadowParams", "binding = 2, std140) uniform ShadowParams");
  PassReflection moved_reflection = text_.reflection;
  reflected_texture(moved_reflection, "receivers")->binding = 7;
  moved_reflection.frag.blocks.front().binding = 2;
  auto visibility = run(PassText{text_.vert, moved, moved_reflection});
  ASSERT_TRUE(visibility.ok()) << visibility.error().to_string();
  EXPECT_EQ(visibility->visibility.data, expected->visibility.data);

  expect_error(run(text_.vert, moved), Error::Kind::bad_input, "query pass",
               "uniform block 'ShadowParams' has binding 2 in the program; the reflection says 0");
  expect_error(run(text_.vert, replaced(text_.frag, "binding = 3) uniform sampler2D receivers",
                                        "binding = 7) uniform sampler2D receivers")),
               Error::Kind::bad_input, "query pass",
               "texture 'receivers' has binding 7 in the program; the reflection says 3");
  const std::string shared = replaced(text_.frag, "binding = 3) uniform sampler2D receivers",
                                      "binding = 2) uniform sampler2D receivers");
  PassReflection shared_reflection = text_.reflection;
  reflected_texture(shared_reflection, "receivers")->binding = 2;
  expect_error(run(PassText{text_.vert, shared, shared_reflection}), Error::Kind::bad_input,
               "query pass", "textures 'shadow_cmp' and 'receivers' both have binding 2");
}

TEST_P(GlExplicitBindings, BlockOffsetsAreChecked) {
  PassReflection shifted = text_.reflection;
  for (ConstantBinding& member : shifted.frag.blocks.front().members) {
    if (member.parameter == "sampling") *member.offset += 16;
  }
  expect_error(run(shifted), Error::Kind::bad_input, "query pass",
               "uniform 'ShadowParams.sampling' is at offset 32 of its block in the program; the "
               "reflection says 48");
}

INSTANTIATE_TEST_SUITE_P(Emitted, GlExplicitBindings, ::testing::Values(Target::glsl450),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

}  // namespace
}  // namespace penumbra::testing
