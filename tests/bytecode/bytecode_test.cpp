// The bytecode stage: fast default variants get Direct3D bytecode beside
// their HLSL, listed in index.json with its profile and size; the compiler's
// errors, warnings and the time limit reach the build with the file and line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "default_library.hpp"
#include "hlsl_compiler.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/model/target_traits.hpp"
#include "penumbra/support/file.hpp"
#include "stages/stages.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

// A few quick variants for the per-file checks; the whole default library
// is compiled once, by DefaultLibraryBytecode.
const std::vector<std::string> kFastVariants = {"hard", "pcf_grid_k3", "pcss_b16_p16_whitepaper16",
                                                "screen_blur_r4"};

// What a file of `profile` starts with: D3D9's version token, or DXBC's magic.
std::string expected_magic(const std::string& profile) {
  if (profile == "vs_3_0") return std::string("\x00\x03\xfe\xff", 4);
  if (profile == "ps_3_0") return std::string("\x00\x03\xff\xff", 4);
  return "DXBC";
}

void expect_bytecode(const Library& library, const std::string& text,
                     const std::optional<BytecodeFile>& bytecode, const std::string& profile) {
  ASSERT_TRUE(bytecode.has_value()) << text << " has no bytecode listed";
  std::filesystem::path expected = text;
  expected.replace_extension(profile.ends_with("_3_0") ? ".d3dbc" : ".dxbc");
  EXPECT_EQ(bytecode->path, expected.string());
  EXPECT_EQ(bytecode->profile, profile) << text;
  const Result<std::string> bytes = read_file(library.root / bytecode->path);
  ASSERT_TRUE(bytes.ok()) << bytes.error().to_string();
  EXPECT_GT(bytecode->size, 0u) << bytecode->path;
  EXPECT_EQ(bytecode->size, bytes->size()) << bytecode->path;
  EXPECT_EQ(bytes->substr(0, 4), expected_magic(profile)) << bytecode->path;
}

class DefaultBytecode : public ::testing::TestWithParam<std::string> {};

TEST_P(DefaultBytecode, EveryPassListsItsBytecodeWithProfileAndSize) {
  auto compiler = recorded_hlsl_compiler();
  ASSERT_TRUE(compiler.ok()) << compiler.error().to_string();
  const Variant* variant = find_default_variant(GetParam());
  ASSERT_NE(variant, nullptr) << GetParam();
  const BuildOptions options{.jobs = 2, .hlsl = {.compiler = *compiler}};
  auto built = TemporaryLibrary::build({*variant}, hlsl_targets(), options);
  ASSERT_TRUE(built.ok()) << built.error().to_string();
  const Library& library = (*built)->library();
  const LibraryVariant& read = library.variants.at(0);
  ASSERT_FALSE(read.passes.empty());
  for (const auto& [pass, by_target] : read.passes) {
    ASSERT_EQ(by_target.size(), hlsl_targets().size()) << to_string(pass);
    for (const auto& [target, files] : by_target) {
      SCOPED_TRACE(std::string(to_string(pass)) + ", " + std::string(to_string(target)));
      const std::string model = std::to_string(traits(target).shader_model);
      expect_bytecode(library, files.vert, files.vert_bytecode, "vs_" + model + "_0");
      expect_bytecode(library, files.frag, files.frag_bytecode, "ps_" + model + "_0");
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Fast, DefaultBytecode, ::testing::ValuesIn(kFastVariants),
                         [](const auto& param_info) { return test_name(param_info.param); });

// Every Direct3D file of the default library compiles with the real
// compiler, with no warning (W####: SampleCmp on a comparison texture
// declared Texture2D<float> truncates nothing), and every Shader Model 3
// file fits the 512 instruction slots of every device by the compiler's own
// count, which index.json lists.
TEST(DefaultLibraryBytecode, EveryDirect3DFileCompilesWithoutWarningsAndFits) {
  auto compiler = recorded_hlsl_compiler();
  ASSERT_TRUE(compiler.ok()) << compiler.error().to_string();
  std::vector<Variant> variants = default_variants();
  // The Direct3D targets each variant is built for (bitmask_backprojection
  // has no hlsl_dx9 form, nor has minmax_pcf above K = 8).
  for (Variant& variant : variants) {
    std::erase_if(variant.targets, [](Target target) { return !traits(target).is_hlsl; });
  }
  const std::filesystem::path out = std::filesystem::path(::testing::TempDir()) /
                                    ("penumbra-bytecode-all-" + std::to_string(::getpid()));
  std::vector<std::string> warnings;
  const auto built = build_library(variants, out, {.jobs = 2, .hlsl = {.compiler = *compiler}},
                                   [&](const Diagnostic& d) {
                                     if (d.severity == Severity::warning)
                                       warnings.push_back(d.where + ": " + d.message);
                                   });
  ASSERT_TRUE(built.ok()) << built.error().to_string();
  const Result<Library> library = load_library(out);
  std::filesystem::remove_all(out);
  ASSERT_TRUE(library.ok()) << library.error().to_string();
  for (const std::string& warning : warnings) ADD_FAILURE() << warning;
  int counted = 0;
  for (const LibraryVariant& variant : library->variants) {
    if (!can_emit(variant.variant, Target::hlsl_dx9)) continue;
    for (const auto& [pass, by_target] : variant.passes) {
      const auto dx9 = by_target.find(Target::hlsl_dx9);
      ASSERT_NE(dx9, by_target.end()) << variant.variant.name;
      for (const auto* bytecode : {&dx9->second.vert_bytecode, &dx9->second.frag_bytecode}) {
        ASSERT_TRUE(bytecode->has_value()) << variant.variant.name;
        EXPECT_GT((*bytecode)->instruction_slots, 0) << (*bytecode)->path;
        EXPECT_LE((*bytecode)->instruction_slots, 512) << (*bytecode)->path;
        ++counted;
      }
    }
  }
  EXPECT_GT(counted, 60);
}

// permutations/largest.json holds the largest counts a manifest allows
// (128 samples, K = 128, a million nodes, blur radius 32): each Direct3D
// file compiles within 10 s, and only the depth-aware radius-32 blur, whose
// weights are unrolled, is over the 512 Shader Model 3 slots, with a
// warning that names it.
TEST(LargestManifestBytecode, EveryDirect3DFileCompilesWithinTenSeconds) {
  auto compiler = recorded_hlsl_compiler();
  ASSERT_TRUE(compiler.ok()) << compiler.error().to_string();
  auto variants =
      load_variants(std::filesystem::path(PENUMBRA_SOURCE_DIR) / "permutations" / "largest.json");
  ASSERT_TRUE(variants.ok()) << variants.error().to_string();
  const std::filesystem::path out = std::filesystem::path(::testing::TempDir()) /
                                    ("penumbra-bytecode-largest-" + std::to_string(::getpid()));
  std::vector<Diagnostic> warnings;
  const auto built = build_library(
      *variants, out,
      {.jobs = 2, .hlsl = {.compiler = *compiler, .timeout = std::chrono::seconds(10)}},
      [&](const Diagnostic& d) {
        if (d.severity == Severity::warning) warnings.push_back(d);
      });
  std::filesystem::remove_all(out);
  ASSERT_TRUE(built.ok()) << built.error().to_string();
  // Every pass file is HLSL here; the function forms are not whole shaders.
  std::size_t function_forms = 0;
  for (const Variant& variant : *variants) {
    if (has_function_form(variant.technique)) function_forms += variant.targets.size();
  }
  EXPECT_EQ(built->bytecode + function_forms, built->files);
  ASSERT_EQ(warnings.size(), 2u);
  for (const Diagnostic& warning : warnings) {
    EXPECT_THAT(warning.where, HasSubstr("variant screen_blur_r32_depth_aware, target hlsl_dx9"));
    EXPECT_THAT(warning.message,
                HasSubstr("instruction slots (vkd3d-compiler's count), over the 512"));
  }
}

// The stage alone, on a file written under a scratch root.
class BytecodeStageTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto compiler = recorded_hlsl_compiler();
    ASSERT_TRUE(compiler.ok()) << compiler.error().to_string();
    options_.compiler = *compiler;
    std::filesystem::remove_all(root_);
  }
  void TearDown() override { std::filesystem::remove_all(root_); }

  // A fragment job of `target` whose text, `text`, is written at `path`.
  ShaderJob written_job(Target target, const std::string& path, const std::string& text) {
    ShaderJob job;
    job.target = target;
    job.stage = ShaderStage::fragment;
    job.source_path = "passes/query.frag";
    job.output_path = path;
    std::filesystem::create_directories((root_ / path).parent_path());
    std::ofstream(root_ / path) << text;
    return job;
  }

  std::filesystem::path root_ = std::filesystem::path(::testing::TempDir()) /
                                ("penumbra-bytecode-stage-" + std::to_string(::getpid()));
  HlslCompilerOptions options_;
};

TEST_F(BytecodeStageTest, CompilerErrorNamesTheFileAndLine) {
  ShaderJob job = written_job(Target::hlsl_dx10, "hlsl_dx10/broken/query.frag.hlsl",
                              "float4 main() : SV_Target\n{\n"
                              "    float4 v = float4(1, 2, 3, 4) garbage;\n"
                              "    return v;\n}\n");
  const Status status = BytecodeStage(root_, options_).process(job);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.error().kind, Error::Kind::compile);
  EXPECT_THAT(status.error().message, HasSubstr("hlsl_dx10/broken/query.frag.hlsl:3:"));
  EXPECT_THAT(status.error().message, HasSubstr("ps_4_0"));
  EXPECT_THAT(status.error().message, HasSubstr("syntax error"));
  EXPECT_THAT(status.error().message, HasSubstr("float4 v = float4(1, 2, 3, 4) garbage;"));
  EXPECT_FALSE(job.bytecode.has_value());
  EXPECT_FALSE(std::filesystem::exists(root_ / "hlsl_dx10/broken/query.frag.dxbc"));
}

TEST_F(BytecodeStageTest, CompilerWarningIsABuildWarningNamingTheFile) {
  ShaderJob job = written_job(Target::hlsl_dx10, "hlsl_dx10/truncates/query.frag.hlsl",
                              "float main() : SV_Target\n{\n"
                              "    float4 v = float4(1, 2, 3, 4);\n    return v;\n}\n");
  const Status status = BytecodeStage(root_, options_).process(job);
  ASSERT_TRUE(status.ok()) << status.error().to_string();
  ASSERT_EQ(job.diagnostics.size(), 1u);
  EXPECT_EQ(job.diagnostics[0].severity, Severity::warning);
  EXPECT_THAT(job.diagnostics[0].message, HasSubstr("hlsl_dx10/truncates/query.frag.hlsl:4:"));
  EXPECT_THAT(job.diagnostics[0].message, HasSubstr("W5300"));
  ASSERT_TRUE(job.bytecode.has_value());
  EXPECT_EQ(job.bytecode->path, "hlsl_dx10/truncates/query.frag.dxbc");
}

// A ps_3_0 shader of 600 dependent multiply-adds is counted on its
// disassembly, listed, and warned about once, naming the limit.
TEST_F(BytecodeStageTest, Sm3ShaderOverTheSlotMinimumWarnsWithTheCount) {
  std::string text = "float4 c;\nfloat4 main(float4 v : TEXCOORD0) : COLOR0\n{\n  float4 x = v;\n";
  for (int i = 0; i < 600; ++i) text += "  x = x * x + c;\n";
  text += "  return x;\n}\n";
  ShaderJob job = written_job(Target::hlsl_dx9, "hlsl_dx9/long/query.frag.hlsl", text);
  const Status status = BytecodeStage(root_, options_).process(job);
  ASSERT_TRUE(status.ok()) << status.error().to_string();
  ASSERT_TRUE(job.bytecode.has_value());
  EXPECT_GE(job.bytecode->instruction_slots, 600);
  ASSERT_EQ(job.diagnostics.size(), 1u);
  EXPECT_EQ(job.diagnostics[0].severity, Severity::warning);
  EXPECT_THAT(job.diagnostics[0].message,
              HasSubstr("ps_3_0 bytecode of " + std::to_string(job.bytecode->instruction_slots) +
                        " instruction slots"));
  EXPECT_THAT(job.diagnostics[0].message, HasSubstr("over the 512"));
}

TEST_F(BytecodeStageTest, TimeLimitFailsTheFile) {
  const Variant* hard = find_default_variant("hard");
  ASSERT_NE(hard, nullptr);
  auto pass = compile_pass(*hard, Target::hlsl_dx9, PassKind::query);
  ASSERT_TRUE(pass.ok()) << pass.error().to_string();
  ShaderJob job = written_job(Target::hlsl_dx9, "hlsl_dx9/hard/query.frag.hlsl", pass->frag.text);
  options_.timeout = std::chrono::milliseconds(1);
  const Status status = BytecodeStage(root_, options_).process(job);
  ASSERT_FALSE(status.ok());
  EXPECT_THAT(status.error().message,
              HasSubstr("hlsl_dx9/hard/query.frag.hlsl: no bytecode after 1 ms"));
  EXPECT_FALSE(job.bytecode.has_value());
}

TEST_F(BytecodeStageTest, TargetsWithoutBytecodePassThrough) {
  ShaderJob job = written_job(Target::glsl450, "glsl450/hard/query.frag", "not HLSL");
  const Status status = BytecodeStage(root_, options_).process(job);
  ASSERT_TRUE(status.ok()) << status.error().to_string();
  EXPECT_FALSE(job.bytecode.has_value());
}

}  // namespace
}  // namespace penumbra::testing
