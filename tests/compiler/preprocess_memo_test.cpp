// The preprocess stage's memo: a job takes an earlier job's text only where
// the macros its files mention agree, and every technique and target still
// gets the text a preprocess of its own makes.
#include "glsl/preprocess_memo.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "glsl/variant_header.hpp"
#include "penumbra/compiler/disk.hpp"
#include "penumbra/compiler/targets.hpp"
#include "stages/stages.hpp"

namespace penumbra {
namespace {

// A shader library of the given files.
class Files final : public ShaderlibSource {
 public:
  explicit Files(std::map<std::string, std::string, std::less<>> files)
      : files_(std::move(files)) {}
  std::optional<std::string> read(std::string_view path) const override {
    const auto found = files_.find(path);
    if (found == files_.end()) return std::nullopt;
    return found->second;
  }
  std::string location(std::string_view path) const override { return std::string(path); }
  bool on_disk() const override { return false; }

 private:
  std::map<std::string, std::string, std::less<>> files_;
};

TEST(PreprocessMemo, HeaderKeyBlanksCommentsAndDefinesNoFileMentions) {
  const std::string header =
      "// variant.glsl for a, target glsl450\n"
      "#define PENUMBRA_TARGET_GLSL450 1\n"
      "#define KERNEL_SIZE 5\n"
      "#define F(x) (x + 1)\n"
      "const float W[1] = float[](1.0);\n";
  EXPECT_EQ(header_key(header, {"KERNEL_SIZE"}),
            "\n\n#define KERNEL_SIZE 5\n\nconst float W[1] = float[](1.0);\n");
  EXPECT_EQ(header_key(header, {"F", "KERNEL_SIZE"}),
            "\n\n#define KERNEL_SIZE 5\n#define F(x) (x + 1)\nconst float W[1] = float[](1.0);\n");
}

TEST(PreprocessMemo, IdentifiersIncludeCommentsAndSkipPunctuation) {
  EXPECT_EQ(identifiers_of("#if A_1 // B\nx = f(2.0) + _c;"),
            (std::set<std::string>{"A_1", "B", "_c", "f", "if", "x"}));
}

TEST(PreprocessMemo, TakesATextOnlyWhereTheMentionedMacrosAgree) {
  const Files files({{"p.frag", "#include \"variant.glsl\"\n#if USED\nfloat x;\n#endif\n"},
                     {"q.frag", "float y;\n"}});
  PreprocessMemo memo(8, files);
  const std::string header = "// for a\n#define USED 1\n#define UNUSED 1\n";
  EXPECT_FALSE(memo.find(ShaderStage::fragment, "p.frag", header));
  memo.add(ShaderStage::fragment, "p.frag", header, {"text", {"p.frag"}});

  const auto same = memo.find(ShaderStage::fragment, "p.frag", "// for b\n#define USED 1\n\n");
  ASSERT_TRUE(same);
  EXPECT_EQ(same->text, "text");
  EXPECT_EQ(same->inputs, std::vector<std::string>{"p.frag"});
  // USED differs, or is not defined at all.
  EXPECT_FALSE(memo.find(ShaderStage::fragment, "p.frag", "#define USED 0\n#define UNUSED 1\n"));
  EXPECT_FALSE(memo.find(ShaderStage::fragment, "p.frag", "\n#define UNUSED 1\n"));
  // A line that is no define is always compared.
  EXPECT_FALSE(memo.find(ShaderStage::fragment, "p.frag", "#define USED 1\nconst int k = 2;\n"));
  // Another stage or source is another text.
  EXPECT_FALSE(memo.find(ShaderStage::vertex, "p.frag", header));
  EXPECT_FALSE(memo.find(ShaderStage::fragment, "q.frag", header));
}

TEST(PreprocessMemo, KeepsOnlyTheLastTexts) {
  const Files files({{"p.frag", "#if A\n#endif\n"}, {"q.frag", ""}});
  PreprocessMemo memo(2, files);
  for (int a = 0; a < 3; ++a) {
    memo.add(ShaderStage::fragment, "p.frag", "#define A " + std::to_string(a) + "\n",
             {std::to_string(a), {"p.frag"}});
  }
  EXPECT_FALSE(memo.find(ShaderStage::fragment, "p.frag", "#define A 0\n"));
  EXPECT_TRUE(memo.find(ShaderStage::fragment, "p.frag", "#define A 2\n"));
}

// The shipped library's targets share a pass's text where the traits its
// files read agree: the query pass reads no clip-space convention, the
// deferred pass does (common/light_clip.glsl).
TEST(PreprocessMemo, TargetsWithTheSameTraitsShareAPassText) {
  Variant variant;
  variant.name = "pcss";
  variant.technique = Technique::pcss;
  variant.keys.blocker_samples = 16;
  variant.keys.pcf_samples = 16;
  variant.blocker_disk = variant.pcf_disk = whitepaper16();
  const auto shaderlib = embedded_shaderlib();
  const auto shares = [&](const char* source, Target target) {
    PreprocessMemo memo(8, *shaderlib);
    for (const Target made : {Target::glsl450, Target::hlsl_dx11}) {
      ShaderJob job;
      job.variant = &variant;
      job.target = made;
      job.source_path = source;
      EXPECT_TRUE(PreprocessStage(shaderlib).process(job).ok());
      memo.add(job.stage, source, variant_header(&variant, made), {job.preprocessed, job.inputs});
    }
    return memo.find(ShaderStage::fragment, source, variant_header(&variant, target)).has_value();
  };
  for (const Target target : {Target::glsl330, Target::essl300, Target::hlsl_dx10}) {
    EXPECT_TRUE(shares("passes/query.frag", target)) << to_string(target);
    EXPECT_TRUE(shares("passes/deferred.frag", target)) << to_string(target);
  }
  EXPECT_TRUE(shares("passes/query.frag", Target::spirv));
  EXPECT_FALSE(shares("passes/deferred.frag", Target::spirv));  // clip z from 0, y up
  EXPECT_FALSE(shares("passes/query.frag", Target::hlsl_dx9));  // no comparison sampler
}

// One stage preprocessing every target in a build's order, its memo at
// work, against a new stage for each job.
class EveryTechnique : public ::testing::TestWithParam<Technique> {};

TEST_P(EveryTechnique, EachTargetGetsTheTextOfItsOwnPreprocess) {
  Variant variant;
  variant.name = std::string(to_string(GetParam()));
  variant.technique = GetParam();
  variant.keys.kernel = 5;
  variant.keys.blocker_samples = 16;
  variant.keys.pcf_samples = 16;
  variant.keys.blur_radius = 2;
  variant.blur_weights = {0.5f, 0.25f};
  variant.blocker_disk = variant.pcf_disk = whitepaper16();
  const auto shaderlib = embedded_shaderlib();
  const PreprocessStage shared(shaderlib);
  const std::pair<const char*, ShaderForm> sources[] = {
      {"passes/query.frag", ShaderForm::pass},
      {"passes/deferred.frag", ShaderForm::pass},
      {"forms/function.frag", ShaderForm::function}};
  for (const auto& [source, form] : sources) {
    for (const Target target : kAllTargets) {
      ShaderJob job;
      job.variant = &variant;
      job.target = target;
      job.source_path = source;
      job.form = form;
      ShaderJob own = job;
      ASSERT_TRUE(shared.process(job).ok()) << job.describe();
      ASSERT_TRUE(PreprocessStage(shaderlib).process(own).ok()) << own.describe();
      EXPECT_EQ(job.preprocessed, own.preprocessed) << job.describe();
      EXPECT_EQ(job.inputs, own.inputs) << job.describe();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(All, EveryTechnique, ::testing::ValuesIn(kAllTechniques),
                         [](const auto& param) { return std::string(to_string(param.param)); });

}  // namespace
}  // namespace penumbra
