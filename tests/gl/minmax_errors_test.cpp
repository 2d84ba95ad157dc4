// What run_query and build_minmax report about the min-max passes: a query
// reading shadow_minmax without them, and errors in either pass named after
// it; min-max passes a query does not need are not built.
#include <gtest/gtest.h>

#include <string>

#include "default_library.hpp"
#include "minmax_test_maps.hpp"

namespace penumbra::testing {
namespace {

// `text` with every `from` replaced by `to`; fails the test if absent.
std::string replaced_all(std::string text, const std::string& from, const std::string& to) {
  EXPECT_NE(text.find(from), std::string::npos) << "'" << from << "' not in the emitted text";
  for (std::size_t at = text.find(from); at != std::string::npos;
       at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

// `text` with its vec4 output `name` cut to a float: main() runs first and
// `name` gets the .x of what it wrote.
std::string scalar_output(const std::string& text, const std::string& name) {
  std::string scalar = replaced_all(text, "out vec4 " + name + ";",
                                    "out float " + name + ";\nvec4 " + name + "_rgba;");
  scalar = replaced_all(scalar, name + " = vec4(", name + "_rgba = vec4(");
  scalar = replaced_all(scalar, "void main()", "void pass_main()");
  return scalar + "\nvoid main()\n{\n    pass_main();\n    " + name + " = " + name +
         "_rgba.x;\n}\n";
}

void expect_error(const Error& error, Error::Kind kind, const std::string& where,
                  const std::string& part) {
  EXPECT_EQ(error.kind, kind) << error.to_string();
  EXPECT_EQ(error.where, where) << error.to_string();
  EXPECT_NE(error.message.find(part), std::string::npos) << error.to_string();
}

class GlMinmaxErrors : public ::testing::TestWithParam<Target> {
 protected:
  void SetUp() override {
    engine_ = make_gl_engine();
    ASSERT_NE(engine_, nullptr);
    auto variant = find_default_variant("minmax_pcf_k8");
    ASSERT_NE(variant, nullptr);
    auto query = emitted_pass(*variant, GetParam(), PassKind::query);
    ASSERT_TRUE(query.ok()) << query.error().to_string();
    query_ = std::move(*query);
    minmax_ = default_minmax_passes(GetParam());
    ASSERT_FALSE(minmax_.init.frag.empty());
    inputs_ = any_scene_inputs();
  }

  Result<GlQueryOutput> run(const GlQueryPasses& passes) {
    return engine_->run_query(passes, inputs_.normalized_depth, inputs_.receivers, inputs_.params);
  }

  std::unique_ptr<GlEngine> engine_;
  PassText query_;
  MinmaxText minmax_;
  SceneInputs inputs_;
};

TEST_P(GlMinmaxErrors, QueryReadingTheMipNeedsItsPasses) {
  auto result = run({query_.view()});
  ASSERT_FALSE(result.ok());
  expect_error(result.error(), Error::Kind::bad_input, "query pass",
               "reads shadow_minmax, the shadow map's min-max mip, but no minmax_init and "
               "minmax_reduce passes were given");
  auto output = run({query_.view(), minmax_.view()});
  ASSERT_TRUE(output.ok()) << output.error().to_string();
}

TEST_P(GlMinmaxErrors, ErrorsNameTheMinmaxPass) {
  MinmaxText broken = minmax_;
  broken.init.frag =
      replaced_all(broken.init.frag, "void main()", "void broken() { oops = 1.0; }\nvoid main()");
  auto init = run({query_.view(), broken.view()});
  ASSERT_FALSE(init.ok());
  expect_error(init.error(), Error::Kind::compile, "minmax_init pass", "oops");

  broken = minmax_;
  broken.reduce.frag = replaced_all(broken.reduce.frag, "minmax_source", "minmax_sourze");
  auto reduce = engine_->build_minmax(broken.view(), inputs_.normalized_depth, inputs_.params);
  ASSERT_FALSE(reduce.ok());
  expect_error(reduce.error(), Error::Kind::bad_input, "minmax_reduce pass",
               "uniform 'minmax_sourze' is active in the program but not in the reflection");

  // The init pass reads the map, not a min-max level: with text and
  // reflection both asking for minmax_source, nothing supplies it.
  broken = minmax_;
  broken.init.frag = replaced_all(broken.init.frag, "shadow_depth", "minmax_source");
  for (TextureBinding& texture : broken.init.reflection.frag.textures) {
    if (texture.name == "shadow_depth") texture.name = "minmax_source";
  }
  auto swapped = engine_->build_minmax(broken.view(), inputs_.normalized_depth, inputs_.params);
  ASSERT_FALSE(swapped.ok());
  expect_error(swapped.error(), Error::Kind::bad_input, "minmax_init pass",
               "nothing supplies texture 'minmax_source'");
}

// Every pass draws into its reflection's GL_RG32F target: a float output is
// refused.
TEST_P(GlMinmaxErrors, OutputsNeedBothChannelsOfTheTarget) {
  PassText query = query_;
  query.frag = scalar_output(query.frag, "visibility");
  auto output = run({query.view(), minmax_.view()});
  ASSERT_FALSE(output.ok());
  expect_error(output.error(), Error::Kind::bad_input, "query pass",
               "fragment output 'visibility' has 1 component(s); its GL_RG32F target takes 2");

  MinmaxText broken = minmax_;
  broken.init.frag = scalar_output(broken.init.frag, "minmax");
  auto init = engine_->build_minmax(broken.view(), inputs_.normalized_depth, inputs_.params);
  ASSERT_FALSE(init.ok());
  expect_error(init.error(), Error::Kind::bad_input, "minmax_init pass",
               "fragment output 'minmax' has 1 component(s); its GL_RG32F target takes 2");
}

TEST_P(GlMinmaxErrors, UnneededMinmaxPassesAreNotBuilt) {
  auto hard = find_default_variant("hard");
  ASSERT_NE(hard, nullptr);
  auto query = emitted_pass(*hard, GetParam(), PassKind::query);
  ASSERT_TRUE(query.ok()) << query.error().to_string();
  MinmaxText broken = minmax_;
  broken.init.frag = "this is not GLSL";
  auto output = run({query->view(), broken.view()});
  ASSERT_TRUE(output.ok()) << output.error().to_string();
  auto plain = run({query->view()});
  ASSERT_TRUE(plain.ok()) << plain.error().to_string();
  EXPECT_EQ(output->visibility.data, plain->visibility.data);
}

INSTANTIATE_TEST_SUITE_P(Emitted, GlMinmaxErrors,
                         ::testing::Values(Target::glsl330, Target::glsl450),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

}  // namespace
}  // namespace penumbra::testing
