// What run_query reports when the GLSL, the names it binds or the inputs are
// wrong: compile and link logs, names outside the interface, missing
// parameters, unusable images.
#include <gtest/gtest.h>

#include <string>

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

class GlErrors : public ::testing::TestWithParam<Target> {
 protected:
  void SetUp() override {
    engine_ = make_gl_engine();
    ASSERT_NE(engine_, nullptr);
    auto variant = default_variant("pcss_b16_p16_whitepaper16");
    ASSERT_NE(variant, nullptr);
    auto text = emitted_pass(*variant, GetParam(), PassKind::query);
    ASSERT_TRUE(text.ok()) << text.error().to_string();
    text_ = std::move(*text);
    inputs_ = any_scene_inputs();
  }

  Result<GlQueryOutput> run(const std::string& vert, const std::string& frag,
                            const ParamBlock& params) {
    return engine_->run_query({{vert, frag}}, inputs_.normalized_depth, inputs_.receivers, params);
  }
  Result<GlQueryOutput> run(const std::string& vert, const std::string& frag) {
    return run(vert, frag, inputs_.params);
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
  auto visibility = run(text_.vert, text_.frag);
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

TEST_P(GlErrors, NamesOutsideTheInterfaceAreRejected) {
  const std::string frag =
      replaced(replaced(text_.frag, "sampler2D receivers;", "sampler2D receiverz;"),
               "textureLod(receivers,", "textureLod(receiverz,");
  expect_error(run(text_.vert, frag), Error::Kind::bad_input, "query pass",
               "sampler 'receiverz' is not part of the shader interface");
  const std::string extra =
      replaced(replaced(text_.frag, "void main()", "uniform float exposure;\nvoid main()"),
               "visibility = vec4(visible,", "visibility = vec4(visible * exposure,");
  expect_error(run(text_.vert, extra), Error::Kind::bad_input, "query pass",
               "uniform 'exposure' is not part of the shader interface");
  const std::string output =
      replaced(replaced(text_.frag, "out vec4 visibility;", "out vec4 shadowing;"),
               "visibility = vec4(", "shadowing = vec4(");
  expect_error(run(text_.vert, output), Error::Kind::bad_input, "query pass",
               "no output 'visibility'");
}

TEST_P(GlErrors, MissingParameterIsNamed) {
  ParamBlock params = inputs_.params;
  params.erase("sampling");
  expect_error(run(text_.vert, text_.frag, params), Error::Kind::bad_input, "query pass",
               "ShadowParams member 'sampling' has no value");
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

using GlExplicitBindings = GlErrors;

// GLSL 4.50's layout(binding) decides the units: moved bindings still run,
// and two samplers on one unit are an error naming both.
TEST_P(GlExplicitBindings, UnitsComeFromTheShader) {
  const std::string moved = replaced(
      replaced(text_.frag, "binding = 3) uniform sampler2D receivers",
               "binding = 7) uniform sampler2D receivers"),
      "binding = 1) uniform sampler2D shadow_depth", "binding = 5) uniform sampler2D shadow_depth");
  auto expected = run(text_.vert, text_.frag);
  ASSERT_TRUE(expected.ok()) << expected.error().to_string();
  auto visibility = run(text_.vert, moved);
  ASSERT_TRUE(visibility.ok()) << visibility.error().to_string();
  EXPECT_EQ(visibility->visibility.data, expected->visibility.data);
  const std::string shared = replaced(text_.frag, "binding = 3) uniform sampler2D receivers",
                                      "binding = 2) uniform sampler2D receivers");
  expect_error(run(text_.vert, shared), Error::Kind::bad_input, "query pass",
               "samplers 'shadow_cmp' and 'receivers' both use texture unit 2");
}

INSTANTIATE_TEST_SUITE_P(Emitted, GlExplicitBindings, ::testing::Values(Target::glsl450),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

INSTANTIATE_TEST_SUITE_P(Emitted, GlErrors, ::testing::Values(Target::glsl330, Target::glsl450),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

}  // namespace
}  // namespace penumbra::testing
