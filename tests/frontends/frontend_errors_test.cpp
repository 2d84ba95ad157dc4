// compile_target_text refuses what it cannot compile with an Error that
// names the target and the file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "default_library.hpp"
#include "emitted_texts.hpp"
#include "penumbra/compiler/text_frontend.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

// The emitted text with a line that no front end accepts after its first line.
std::string broken(const std::string& text) {
  const std::size_t line_two = text.find('\n') + 1;
  return text.substr(0, line_two) + "this is not a shader;\n" + text.substr(line_two);
}

class FrontEndErrors : public ::testing::TestWithParam<Target> {};

TEST_P(FrontEndErrors, ABrokenTextNamesTheTargetAndTheFile) {
  const Variant* hard = find_default_variant("hard");
  ASSERT_NE(hard, nullptr);
  const std::vector<EmittedStage> stages = emitted_stages(*hard, GetParam());
  ASSERT_FALSE(stages.empty());
  const std::string target(to_string(GetParam()));
  const std::string file = "out/" + target + "/common/depth.vert";

  // The unbroken text compiles: the error below is the broken line's.
  ASSERT_TRUE(compile_target_text(GetParam(), ShaderStage::vertex, stages[0].compiled.text, file));
  auto result =
      compile_target_text(GetParam(), ShaderStage::vertex, broken(stages[0].compiled.text), file);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().kind, Error::Kind::compile);
  EXPECT_EQ(result.error().where, file);
  EXPECT_THAT(result.error().message, HasSubstr("rejected the " + target + " text"));
  EXPECT_THAT(result.error().message, HasSubstr(file + ":"));  // glslang's log, at the line
}

INSTANTIATE_TEST_SUITE_P(TextTargets, FrontEndErrors, ::testing::ValuesIn(text_targets()),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

TEST(FrontEndErrors, SpirvHasNoTextToCompile) {
  auto result = compile_target_text(Target::spirv, ShaderStage::vertex, "", "depth.vert.spv");
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().kind, Error::Kind::bad_input);
  EXPECT_EQ(result.error().where, "depth.vert.spv");
}

TEST(FrontEndErrors, AShimThatDoesNotApplyNamesItselfTheTargetAndTheFile) {
  // ESSL 3.00 text must begin with its #version line.
  auto result = compile_target_text(Target::essl300, ShaderStage::fragment,
                                    "// comment\n#version 300 es\nvoid main() {}\n", "q.frag");
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().where, "q.frag");
  EXPECT_THAT(result.error().message, HasSubstr("essl300"));
  EXPECT_THAT(result.error().message, HasSubstr("essl300-version-310"));
}

}  // namespace
}  // namespace penumbra::testing
