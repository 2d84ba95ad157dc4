// The build pipeline: every technique compiles for every target, target
// rules name the construct, failures leave no output, output is stable.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/disk.hpp"
#include "penumbra/compiler/library.hpp"
#include "stages/stages.hpp"

namespace penumbra {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

Variant make_variant(Technique technique) {
  Variant v;
  v.technique = technique;
  v.targets.assign(kAllTargets.begin(), kAllTargets.end());
  switch (technique) {
    case Technique::hard:
      break;
    case Technique::pcf_grid:
      v.keys.kernel = 5;
      break;
    case Technique::pcf_poisson:
      v.keys.pcf_samples = 16;
      v.keys.disk = "whitepaper16";
      v.pcf_disk = whitepaper16();
      break;
    case Technique::pcss:
      v.keys.blocker_samples = 16;
      v.keys.pcf_samples = 16;
      v.keys.disk = "whitepaper16";
      v.blocker_disk = whitepaper16();
      v.pcf_disk = whitepaper16();
      break;
    case Technique::minmax_pcf:
      v.keys.kernel = 12;
      break;
    case Technique::backprojection:
      break;
    case Technique::pcss_minmax:
      v.keys.pcf_samples = 16;
      v.keys.disk = "whitepaper16";
      v.pcf_disk = whitepaper16();
      break;
  }
  v.name = variant_name(technique, v.keys);
  return v;
}

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name)
      : path(std::filesystem::path(::testing::TempDir()) / ("penumbra-pipeline-" + name)) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

class EveryTechniqueAndTarget : public ::testing::TestWithParam<std::tuple<Technique, Target>> {};

TEST_P(EveryTechniqueAndTarget, QueryPassCompilesWithTheSharedInterface) {
  const auto [technique, target] = GetParam();
  const Variant variant = make_variant(technique);
  auto pass = compile_pass(variant, target, PassKind::query);
  ASSERT_TRUE(pass.ok()) << pass.error().to_string();
  EXPECT_EQ(pass->frag.text.empty(), target == Target::spirv);

  const ShaderInterface& frag = pass->frag.interface;
  ASSERT_EQ(frag.uniform_blocks.size(), 1u);
  const UniformBlock& block = frag.uniform_blocks[0];
  EXPECT_EQ(block.type_name, "ShadowParams");
  ASSERT_EQ(block.members.size(), 4u);
  EXPECT_EQ(block.members[1].name, "light");
  EXPECT_EQ(block.members[1].offset, 16u);
  bool has_cmp = false;
  for (const SampledImage& image : frag.sampled_images) {
    has_cmp = has_cmp || (image.name == "shadow_cmp" && image.comparison);
  }
  // Only hlsl_dx9 makes its compares in the shader; hard needs no bilinear compare.
  EXPECT_EQ(has_cmp, target != Target::hlsl_dx9 && technique != Technique::hard);
}

INSTANTIATE_TEST_SUITE_P(All, EveryTechniqueAndTarget,
                         ::testing::Combine(::testing::ValuesIn(kAllTechniques),
                                            ::testing::ValuesIn(kAllTargets)),
                         [](const auto& param_info) {
                           return std::string(to_string(std::get<0>(param_info.param))) + "_" +
                                  std::string(to_string(std::get<1>(param_info.param)));
                         });

TEST(TargetText, Dx9UsesRegistersPointReadsAndNoComparisonSampler) {
  auto pass = compile_pass(make_variant(Technique::pcss), Target::hlsl_dx9, PassKind::query);
  ASSERT_TRUE(pass.ok()) << pass.error().to_string();
  const std::string& text = pass->frag.text;
  EXPECT_THAT(text, HasSubstr("uniform float4 params_light : register(c1);"));
  EXPECT_THAT(text, HasSubstr("tex2Dlod(shadow_depth"));
  EXPECT_THAT(text, Not(HasSubstr("cbuffer")));
  EXPECT_THAT(text, Not(HasSubstr("tex2Dproj")));
  EXPECT_THAT(text, Not(HasSubstr("SampleCmp")));
}

TEST(TargetText, Dx10UsesSampleCmpLevelZeroAndSampleLevel) {
  auto pass = compile_pass(make_variant(Technique::pcss), Target::hlsl_dx10, PassKind::query);
  ASSERT_TRUE(pass.ok()) << pass.error().to_string();
  const std::string& text = pass->frag.text;
  EXPECT_THAT(text, HasSubstr("shadow_cmp.SampleCmpLevelZero("));
  EXPECT_THAT(text, HasSubstr("shadow_depth.SampleLevel("));
  EXPECT_THAT(text, HasSubstr("cbuffer ShadowParams : register(b0)"));
  EXPECT_THAT(text, Not(HasSubstr(".Sample(")));
}

TEST(TargetText, SourceNamesSurvive) {
  auto pass = compile_pass(make_variant(Technique::pcss), Target::glsl450, PassKind::query);
  ASSERT_TRUE(pass.ok()) << pass.error().to_string();
  for (const char* name :
       {"FindBlocker", "PenumbraSize", "PCF_Filter", "avgBlockerDepth", "searchWidth",
        "filterRadiusUV", "shadow_compare_bilinear", "POISSON_DISK[i]"}) {
    EXPECT_THAT(pass->frag.text, HasSubstr(name));
  }
}

TEST(TargetRules, ComparisonSamplingIsRejectedForDx9WithVariantTargetAndConstruct) {
  // SPIR-V compiled for a comparison-sampler target, then emitted as DX9.
  const Variant variant = make_variant(Technique::pcf_grid);
  ShaderJob job;
  job.variant = &variant;
  job.target = Target::spirv;
  job.pass = PassKind::query;
  job.stage = ShaderStage::fragment;
  job.source_path = "passes/query.frag";
  ASSERT_TRUE(PreprocessStage().process(job).ok());
  ASSERT_TRUE(CompileStage().process(job).ok());
  job.target = Target::hlsl_dx9;
  Status status = CrossCompileStage().process(job);
  ASSERT_FALSE(status.ok());
  EXPECT_THAT(status.error().to_string(), HasSubstr("variant pcf_grid_k5"));
  EXPECT_THAT(status.error().to_string(), HasSubstr("hlsl_dx9"));
  EXPECT_THAT(status.error().to_string(), HasSubstr("SampleCmpLevelZero"));
}

TEST(BuildLibrary, AShaderThatFailsToCompileLeavesThePreviousOutput) {
  TempDir dir("fail");
  const auto out = dir.path / "out";
  std::filesystem::create_directories(out);
  std::ofstream(out / "index.json") << "{}";  // a previous library
  std::ofstream(out / "keep.txt") << "previous";
  Variant broken = make_variant(Technique::pcf_poisson);
  broken.keys.pcf_samples = 0;  // an array of size 0 does not compile
  broken.pcf_disk->points.clear();
  broken.name = "pcf_poisson_p0_broken";
  auto result = build_library(std::span(&broken, 1), out, {}, ignore_diagnostics());
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().kind, Error::Kind::compile);
  EXPECT_THAT(result.error().to_string(), HasSubstr("variant pcf_poisson_p0_broken"));
  EXPECT_THAT(result.error().to_string(), HasSubstr("passes/query.frag"));
  EXPECT_EQ(slurp(out / "keep.txt"), "previous");
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::recursive_directory_iterator(dir.path)) {
    ++entries;
  }
  EXPECT_EQ(entries, 3u) << "staging directory left behind";
}

TEST(BuildLibrary, RefusesToReplaceAnythingButALibrary) {
  TempDir dir("refuse");
  const Variant hard = make_variant(Technique::hard);
  std::ofstream(dir.path / "notes.txt") << "mine";
  auto over_file =
      build_library(std::span(&hard, 1), dir.path / "notes.txt", {}, ignore_diagnostics());
  ASSERT_FALSE(over_file.ok());
  EXPECT_THAT(over_file.error().to_string(), HasSubstr("not a directory"));
  EXPECT_EQ(slurp(dir.path / "notes.txt"), "mine");
  std::filesystem::create_directories(dir.path / "docs");
  std::ofstream(dir.path / "docs" / "thesis.tex") << "mine";
  auto over_dir = build_library(std::span(&hard, 1), dir.path / "docs", {}, ignore_diagnostics());
  ASSERT_FALSE(over_dir.ok());
  EXPECT_THAT(over_dir.error().to_string(), HasSubstr("without index.json"));
  EXPECT_EQ(slurp(dir.path / "docs" / "thesis.tex"), "mine");
  // An empty directory and an earlier library are fine.
  std::filesystem::create_directories(dir.path / "empty");
  EXPECT_TRUE(
      build_library(std::span(&hard, 1), dir.path / "empty", {}, ignore_diagnostics()).ok());
  EXPECT_TRUE(
      build_library(std::span(&hard, 1), dir.path / "empty", {}, ignore_diagnostics()).ok());
}

TEST(LoadLibrary, UnknownPassesAndSchemasAreErrorsNamingTheJsonPath) {
  TempDir dir("load");
  const Variant hard = make_variant(Technique::hard);
  ASSERT_TRUE(build_library(std::span(&hard, 1), dir.path / "out", {}, ignore_diagnostics()).ok());
  const auto index = dir.path / "out" / "index.json";
  const std::string text = slurp(index);
  std::string renamed = text;
  renamed.replace(renamed.find("\"query\": {"), 7, "\"blurry\"");
  std::ofstream(index) << renamed;
  auto bad_pass = load_library(dir.path / "out");
  ASSERT_FALSE(bad_pass.ok());
  EXPECT_THAT(bad_pass.error().to_string(), HasSubstr("/variants/0/passes/blurry"));
  std::string schema = text;
  schema.replace(schema.find("\"schema\": 1"), 11, "\"schema\": 7");
  std::ofstream(index) << schema;
  auto bad_schema = load_library(dir.path / "out");
  ASSERT_FALSE(bad_schema.ok());
  EXPECT_THAT(bad_schema.error().to_string(), HasSubstr("/schema"));
}

TEST(BuildLibrary, OutputIsIdenticalAcrossRunsAndThreadCounts) {
  TempDir dir("stable");
  const std::vector<Variant> variants = {make_variant(Technique::pcss),
                                         make_variant(Technique::hard)};
  ASSERT_TRUE(build_library(variants, dir.path / "a", {.jobs = 1}, ignore_diagnostics()).ok());
  ASSERT_TRUE(build_library(variants, dir.path / "b", {.jobs = 2}, ignore_diagnostics()).ok());
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir.path / "a")) {
    if (!entry.is_regular_file()) continue;
    const auto rel = std::filesystem::relative(entry.path(), dir.path / "a");
    EXPECT_EQ(slurp(entry.path()), slurp(dir.path / "b" / rel)) << rel;
    ++files;
  }
  EXPECT_EQ(files, 6u * 3u + 2u * 6u + 1u);  // shared x targets, query x variants x targets, index
}

TEST(BuildLibrary, IndexHoldsTheBakedDiskValuesExactly) {
  TempDir dir("index");
  Variant v = make_variant(Technique::pcss);
  auto generated = generate_disk({.count = 25, .seed = 7, .method = "best_candidate"});
  ASSERT_TRUE(generated.ok());
  v.blocker_disk = *generated;
  v.keys.blocker_samples = 25;
  v.keys.disk = "custom";
  v.name = variant_name(v.technique, v.keys);
  ASSERT_TRUE(build_library(std::span(&v, 1), dir.path / "out", {}, ignore_diagnostics()).ok());
  auto library = load_library(dir.path / "out");
  ASSERT_TRUE(library.ok()) << library.error().to_string();
  const LibraryVariant* loaded = library->find(v.name);
  ASSERT_NE(loaded, nullptr);
  EXPECT_EQ(loaded->variant.blocker_disk->points, v.blocker_disk->points);
  EXPECT_EQ(loaded->variant.pcf_disk->points, v.pcf_disk->points);
  // Every emitted file starts with (or, for GLSL, right after #version) a
  // comment naming the variant and its keys.
  const std::string text = slurp(dir.path / "out" / "hlsl_dx9" / v.name / "query.frag.hlsl");
  EXPECT_THAT(text.substr(0, 200),
              HasSubstr("Variant " + v.name + " (technique pcss, blocker_samples 25"));
  // Two different disks keep their own source names.
  EXPECT_THAT(text, HasSubstr("BLOCKER_DISK[25]"));
  EXPECT_THAT(text, HasSubstr("PCF_DISK[16]"));
}

}  // namespace
}  // namespace penumbra
