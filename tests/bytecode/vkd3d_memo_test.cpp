// Vkd3dMemo: translators that share one run vkd3d-compiler once per
// distinct input, whatever file holds it, and keep no failure. A second
// translator whose compiler does not exist shows which calls ran it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "hlsl_compiler.hpp"
#include "penumbra/compiler/bytecode_frontend.hpp"
#include "penumbra/support/file.hpp"
#include "penumbra/support/scratch_file.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

constexpr const char* kRed = "float4 main() : SV_Target { return float4(1, 0, 0, 1); }\n";
constexpr const char* kGreen = "float4 main() : SV_Target { return float4(0, 1, 0, 1); }\n";

struct Translators {
  BytecodeTranslator real;    // the recorded vkd3d-compiler
  BytecodeTranslator absent;  // no compiler: only the memo can answer
};

Result<Translators> sharing_one_memo() {
  PENUMBRA_TRY_ASSIGN(std::filesystem::path compiler, recorded_hlsl_compiler());
  auto memo = std::make_shared<Vkd3dMemo>();
  return Translators{{compiler, std::chrono::milliseconds(60'000), memo},
                     {"/nonexistent/vkd3d-compiler", std::chrono::milliseconds(60'000), memo}};
}

TEST(Vkd3dMemo, TheSameTextIsCompiledOnceIntoEveryOutput) {
  auto translators = sharing_one_memo();
  ASSERT_TRUE(translators) << translators.error().to_string();
  const ScratchFile first("memo", ".dxbc"), second("memo", ".dxbc");
  ASSERT_TRUE(compile_hlsl_bytecode(translators->real, Target::hlsl_dx11, ShaderStage::fragment,
                                    kRed, "red.hlsl", first.path()));
  ASSERT_TRUE(compile_hlsl_bytecode(translators->absent, Target::hlsl_dx11, ShaderStage::fragment,
                                    kRed, "red again.hlsl", second.path()));
  EXPECT_EQ(read_file(first.path()).value(), read_file(second.path()).value());
  // Another text, or the same text for another target, is compiled again.
  EXPECT_FALSE(compile_hlsl_bytecode(translators->absent, Target::hlsl_dx11, ShaderStage::fragment,
                                     kGreen, "green.hlsl", second.path()));
  EXPECT_FALSE(compile_hlsl_bytecode(translators->absent, Target::hlsl_dx10, ShaderStage::fragment,
                                     kRed, "red.hlsl", second.path()));
}

TEST(Vkd3dMemo, TheSameBytecodeIsTranslatedOnceFromAnyFile) {
  auto translators = sharing_one_memo();
  ASSERT_TRUE(translators) << translators.error().to_string();
  const ScratchFile bytecode("memo", ".dxbc"), copy("memo", ".dxbc");
  ASSERT_TRUE(compile_hlsl_bytecode(translators->real, Target::hlsl_dx11, ShaderStage::fragment,
                                    kRed, "red.hlsl", bytecode.path()));
  ASSERT_TRUE(write_file(copy.path(), read_file(bytecode.path()).value()));
  auto translated = translate_bytecode(translators->real, Target::hlsl_dx11, ShaderStage::fragment,
                                       bytecode.path());
  ASSERT_TRUE(translated) << translated.error().to_string();
  auto again = translate_bytecode(translators->absent, Target::hlsl_dx11, ShaderStage::fragment,
                                  copy.path());
  ASSERT_TRUE(again) << again.error().to_string();
  EXPECT_EQ(again->spirv, translated->spirv);
  EXPECT_EQ(again->front_end, translated->front_end);
  // The same bytes as the vertex stage's are translated again.
  EXPECT_FALSE(
      translate_bytecode(translators->absent, Target::hlsl_dx11, ShaderStage::vertex, copy.path()));
}

TEST(Vkd3dMemo, AFailureIsNotKeptAndNamesItsOwnFile) {
  auto translators = sharing_one_memo();
  ASSERT_TRUE(translators) << translators.error().to_string();
  const ScratchFile output("memo", ".dxbc");
  const std::string broken = "float4 main() : SV_Target { return undeclared; }\n";
  for (const std::string name : {"first.hlsl", "second.hlsl"}) {
    const Status status = compile_hlsl_bytecode(translators->real, Target::hlsl_dx11,
                                                ShaderStage::fragment, broken, name, output.path());
    ASSERT_FALSE(status);
    EXPECT_EQ(status.error().where, name);
    EXPECT_THAT(status.error().message, HasSubstr("vkd3d-compiler ps_5_0"));
  }
}

}  // namespace
}  // namespace penumbra::testing
