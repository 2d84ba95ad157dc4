// The build pipeline: every technique compiles for every target, target
// rules name the construct, failures leave no output, output is stable.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "glsl/variant_header.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/disk.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/compiler/targets.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/model/shader_contract.hpp"
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
      v.keys.kernel = 8;  // the largest hlsl_dx9 counts exactly
      break;
    case Technique::backprojection:
      break;
    case Technique::pcss_minmax:
      v.keys.pcf_samples = 16;
      v.keys.disk = "whitepaper16";
      v.pcf_disk = whitepaper16();
      break;
    case Technique::screen_blur:
      v.keys.blur_radius = 4;
      v.blur_weights = gaussian_weights(4);
      break;
    case Technique::bitmask_backprojection:
      v.keys.light_bits = 64;
      // Shader Model 3 has no integer bit operations.
      std::erase(v.targets, Target::hlsl_dx9);
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
  if (!can_emit(technique, target)) {
    // The target's rules refuse it even past the manifest's check.
    ASSERT_FALSE(pass.ok());
    EXPECT_THAT(pass.error().message, HasSubstr("integer"));
    return;
  }
  ASSERT_TRUE(pass.ok()) << pass.error().to_string();
  EXPECT_EQ(pass->frag.text.empty(), target == Target::spirv);

  const ShaderInterface& frag = pass->frag.interface;
  ASSERT_EQ(frag.uniform_blocks.size(), 1u);
  const UniformBlock& block = frag.uniform_blocks[0];
  EXPECT_EQ(block.type_name, "ShadowParams");
  ASSERT_EQ(block.members.size(), 6u);
  EXPECT_EQ(block.members[1].name, "light");
  EXPECT_EQ(block.members[1].offset, 16u);
  EXPECT_EQ(block.members[4].name, "source_size");
  EXPECT_EQ(block.members[4].offset, 64u);
  EXPECT_EQ(block.members[5].name, "minmax_info");
  EXPECT_EQ(block.members[5].offset, 80u);
  bool has_cmp = false;
  bool has_minmax = false;
  for (const SampledImage& image : frag.sampled_images) {
    has_cmp = has_cmp || (image.name == "shadow_cmp" && image.comparison);
    has_minmax = has_minmax || (image.name == "shadow_minmax" && image.binding == 4u);
  }
  // Only hlsl_dx9 makes its compares in the shader; hard, minmax_pcf and
  // the back-projections make no bilinear compare.
  const bool bilinear = technique != Technique::hard && technique != Technique::minmax_pcf &&
                        technique != Technique::backprojection &&
                        technique != Technique::bitmask_backprojection &&
                        technique != Technique::screen_blur;
  EXPECT_EQ(has_cmp, target != Target::hlsl_dx9 && bilinear);
  EXPECT_EQ(has_minmax, uses_minmax_mip(technique));
  // visibility (.x) and the texels read (.y).
  ASSERT_EQ(frag.outputs.size(), 1u);
  EXPECT_EQ(frag.outputs[0].name, "visibility");
}

INSTANTIATE_TEST_SUITE_P(All, EveryTechniqueAndTarget,
                         ::testing::Combine(::testing::ValuesIn(kAllTechniques),
                                            ::testing::ValuesIn(kAllTargets)),
                         [](const auto& param_info) {
                           return std::string(to_string(std::get<0>(param_info.param))) + "_" +
                                  std::string(to_string(std::get<1>(param_info.param)));
                         });

// The traversal variants: brute force, and a work bound that needs all three
// nested loops (over 255^2 visits).
class TraversalVariants : public ::testing::TestWithParam<std::tuple<int, Target>> {};

// 0: minmax_pcf brute force, 1: backprojection brute force, 2: backprojection
// with the largest max_nodes.
Variant traversal_variant(int which) {
  Variant v = make_variant(which == 0 ? Technique::minmax_pcf : Technique::backprojection);
  if (which < 2) v.keys.traversal = std::string(kBruteForceTraversal);
  if (which == 2) v.keys.max_nodes = kMaxMaxNodes;
  v.name = variant_name(v.technique, v.keys);
  return v;
}

TEST_P(TraversalVariants, CompileAndPassTheTargetRules) {
  const auto [which, target] = GetParam();
  const Variant variant = traversal_variant(which);
  auto pass = compile_pass(variant, target, PassKind::query);
  ASSERT_TRUE(pass.ok()) << pass.error().to_string();
  if (target == Target::glsl450) {
    if (variant.keys.traversal) {
      EXPECT_THAT(pass->frag.text, HasSubstr("shadow_texel("));
      EXPECT_THAT(pass->frag.text, Not(HasSubstr("minmax_descend")));
    } else {
      EXPECT_THAT(pass->frag.text, HasSubstr("minmax_descend"));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(All, TraversalVariants,
                         ::testing::Combine(::testing::Values(0, 1, 2),
                                            ::testing::ValuesIn(kAllTargets)),
                         [](const auto& param_info) {
                           return traversal_variant(std::get<0>(param_info.param)).name + "_" +
                                  std::string(to_string(std::get<1>(param_info.param)));
                         });

bool binds_image(const ShaderInterface& iface, std::string_view name, std::uint32_t binding) {
  return std::ranges::any_of(iface.sampled_images, [&](const SampledImage& image) {
    return image.name == name && image.binding == binding;
  });
}

class MinmaxPasses : public ::testing::TestWithParam<Target> {};

TEST_P(MinmaxPasses, CompileForEveryTargetAndReadTheirSource) {
  const Target target = GetParam();
  const Variant variant = make_variant(Technique::minmax_pcf);
  auto init = compile_pass(variant, target, PassKind::minmax_init);
  ASSERT_TRUE(init.ok()) << init.error().to_string();
  auto reduce = compile_pass(variant, target, PassKind::minmax_reduce);
  ASSERT_TRUE(reduce.ok()) << reduce.error().to_string();
  EXPECT_TRUE(binds_image(init->frag.interface, "shadow_depth", 1u));
  EXPECT_FALSE(binds_image(init->frag.interface, "minmax_source", 5u));
  EXPECT_TRUE(binds_image(reduce->frag.interface, "minmax_source", 5u));
  EXPECT_FALSE(binds_image(reduce->frag.interface, "shadow_depth", 1u));
  for (const CompiledPass* pass : {&*init, &*reduce}) {
    ASSERT_EQ(pass->frag.interface.outputs.size(), 1u);
    EXPECT_EQ(pass->frag.interface.outputs[0].name, "minmax");
    ASSERT_EQ(pass->vert.interface.outputs.size(), 1u);
    EXPECT_EQ(pass->vert.interface.outputs[0].name, "screen_uv");
  }
}

INSTANTIATE_TEST_SUITE_P(All, MinmaxPasses, ::testing::ValuesIn(kAllTargets),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

TEST(MinmaxPasses, OnlyForTechniquesThatReadTheMip) {
  auto pass = compile_pass(make_variant(Technique::pcss), Target::spirv, PassKind::minmax_reduce);
  ASSERT_FALSE(pass.ok());
  EXPECT_EQ(pass.error().to_string(),
            "variant pcss_b16_p16_whitepaper16: has no minmax_reduce pass (technique pcss does "
            "not use it)");
}

Variant depth_aware_blur() {
  Variant v = make_variant(Technique::screen_blur);
  v.keys.depth_aware = true;
  v.name = variant_name(v.technique, v.keys);
  return v;
}

class ScreenBlurPasses : public ::testing::TestWithParam<Target> {};

TEST_P(ScreenBlurPasses, CompileForEveryTargetWithTheirImagesAndOutputs) {
  const Target target = GetParam();
  for (const Variant& variant : {make_variant(Technique::screen_blur), depth_aware_blur()}) {
    const bool aware = variant.keys.depth_aware.value_or(false);
    for (PassKind kind : {PassKind::blur_h, PassKind::blur_v}) {
      auto pass = compile_pass(variant, target, kind);
      ASSERT_TRUE(pass.ok()) << pass.error().to_string();
      const ShaderInterface& frag = pass->frag.interface;
      EXPECT_TRUE(binds_image(frag, "screen_factor", 6u)) << variant.name;
      EXPECT_EQ(binds_image(frag, "receivers", 3u), aware) << variant.name;
      EXPECT_FALSE(binds_image(frag, "shadow_depth", 1u)) << variant.name;
      ASSERT_EQ(frag.outputs.size(), 1u);
      EXPECT_EQ(frag.outputs[0].name, "blurred");
      ASSERT_EQ(frag.uniform_blocks.size(), 1u);
      EXPECT_EQ(frag.uniform_blocks[0].type_name, "ShadowParams");
    }
  }
  auto composite = compile_pass(make_variant(Technique::screen_blur), target, PassKind::composite);
  ASSERT_TRUE(composite.ok()) << composite.error().to_string();
  const ShaderInterface& frag = composite->frag.interface;
  EXPECT_TRUE(binds_image(frag, "screen_factor", 6u));
  EXPECT_TRUE(binds_image(frag, "scene_colour", 7u));
  EXPECT_EQ(frag.sampled_images.size(), 2u);
  ASSERT_EQ(frag.outputs.size(), 1u);
  EXPECT_EQ(frag.outputs[0].name, "colour");
  ASSERT_EQ(composite->vert.interface.outputs.size(), 1u);
  EXPECT_EQ(composite->vert.interface.outputs[0].name, "screen_uv");
  // The factor pass makes nine point compares: no comparison sampler anywhere.
  auto query = compile_pass(make_variant(Technique::screen_blur), target, PassKind::query);
  ASSERT_TRUE(query.ok()) << query.error().to_string();
  EXPECT_FALSE(binds_image(query->frag.interface, "shadow_cmp", 2u));
  EXPECT_TRUE(binds_image(query->frag.interface, "receivers", 3u));
}

INSTANTIATE_TEST_SUITE_P(All, ScreenBlurPasses, ::testing::ValuesIn(kAllTargets),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

TEST(ScreenBlurPasses, OnlyForScreenBlur) {
  for (PassKind kind : {PassKind::blur_h, PassKind::blur_v, PassKind::composite}) {
    auto pass = compile_pass(make_variant(Technique::hard), Target::spirv, kind);
    ASSERT_FALSE(pass.ok());
    EXPECT_EQ(pass.error().to_string(), "variant hard: has no " + std::string(to_string(kind)) +
                                            " pass (technique hard does not use it)");
  }
  for (PassKind kind : {PassKind::minmax_init, PassKind::minmax_reduce}) {
    EXPECT_FALSE(compile_pass(make_variant(Technique::screen_blur), Target::spirv, kind).ok());
  }
}

TEST(ScreenBlurPasses, HeaderBakesRadiusWeightsAndDepthRule) {
  const Variant blur = make_variant(Technique::screen_blur);
  const std::string header = variant_header(&blur, Target::hlsl_dx9);
  EXPECT_THAT(header, HasSubstr("#define PENUMBRA_TECHNIQUE_SCREEN_BLUR 1\n"));
  EXPECT_THAT(header, HasSubstr("#define BLUR_RADIUS 4\n"));
  EXPECT_THAT(header, HasSubstr("#define PENUMBRA_DEPTH_AWARE 0\n"));
  EXPECT_THAT(header, HasSubstr("#define BLUR_DEPTH_TOLERANCE 0.02\n"));
  std::string weights = "const float BLUR_WEIGHTS[9] = float[](";
  for (std::size_t i = 0; i < blur.blur_weights.size(); ++i) {
    weights += (i == 0 ? "\n  " : ",\n  ") + glsl_float(blur.blur_weights[i]);
  }
  EXPECT_THAT(header, HasSubstr(weights + ");\n"));
  EXPECT_THAT(variant_header(&blur, Target::spirv), HasSubstr("#define BLUR_RADIUS 4\n"));
  const Variant aware = depth_aware_blur();
  EXPECT_THAT(variant_header(&aware, Target::glsl330),
              HasSubstr("#define PENUMBRA_DEPTH_AWARE 1\n"));
  // Other techniques get none of it.
  const Variant grid = make_variant(Technique::pcf_grid);
  EXPECT_THAT(variant_header(&grid, Target::spirv), Not(HasSubstr("BLUR_")));
}

TEST(ScreenBlurPasses, TapsLoopOverTheBakedWeights) {
  auto pass = compile_pass(depth_aware_blur(), Target::glsl450, PassKind::blur_h);
  ASSERT_TRUE(pass.ok()) << pass.error().to_string();
  EXPECT_THAT(pass->frag.text, HasSubstr("BLUR_WEIGHTS"));
  EXPECT_THAT(pass->frag.text, HasSubstr("blur_factor"));
  EXPECT_THAT(pass->frag.text, Not(HasSubstr("gl_FragCoord")));
}

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

TEST(PreprocessShader, IsThePipelinesFirstStageAlone) {
  const Variant variant = make_variant(Technique::pcss);
  auto text = preprocess_shader(variant, Target::hlsl_dx9, PassKind::query, ShaderStage::fragment);
  ASSERT_TRUE(text.ok()) << text.error().to_string();
  EXPECT_THAT(*text, HasSubstr("#version 450"));
  EXPECT_THAT(*text, HasSubstr("FindBlocker"));
  EXPECT_THAT(*text, Not(HasSubstr("#include")));

  ShaderJob job;
  job.variant = &variant;
  job.target = Target::hlsl_dx9;
  job.stage = ShaderStage::fragment;
  job.source_path = "passes/query.frag";
  ASSERT_TRUE(PreprocessStage(embedded_shaderlib()).process(job).ok());
  EXPECT_EQ(*text, job.preprocessed);

  auto missing =
      preprocess_shader(variant, Target::spirv, PassKind::minmax_init, ShaderStage::fragment);
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().kind, Error::Kind::bad_input);
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
  ASSERT_TRUE(PreprocessStage(embedded_shaderlib()).process(job).ok());
  ASSERT_TRUE(CompileStage(embedded_shaderlib()).process(job).ok());
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
  std::ofstream(out / "index.json") << R"({"generator": "penumbra 0.1.0"})";  // a previous library
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
  EXPECT_THAT(over_dir.error().to_string(), HasSubstr("not a penumbra library"));
  EXPECT_EQ(slurp(dir.path / "docs" / "thesis.tex"), "mine");
  // An index.json that penumbra did not write does not make a library.
  std::ofstream(dir.path / "docs" / "index.json") << R"({"title": "my thesis"})";
  auto over_index = build_library(std::span(&hard, 1), dir.path / "docs", {}, ignore_diagnostics());
  ASSERT_FALSE(over_index.ok());
  EXPECT_THAT(over_index.error().to_string(), HasSubstr("not a penumbra library"));
  EXPECT_EQ(slurp(dir.path / "docs" / "thesis.tex"), "mine");
  // An empty directory and an earlier library are fine.
  std::filesystem::create_directories(dir.path / "empty");
  EXPECT_TRUE(
      build_library(std::span(&hard, 1), dir.path / "empty", {}, ignore_diagnostics()).ok());
  EXPECT_TRUE(
      build_library(std::span(&hard, 1), dir.path / "empty", {}, ignore_diagnostics()).ok());
}

// minmax_pcf promises the exact count: past the manifest's check, a kernel
// whose walk hlsl_dx9's cap would stop short is refused when compiled
// directly, and in a library written by hand.
TEST(TargetRules, MinmaxPcfIsRefusedWhereItCannotCountExactly) {
  Variant variant = make_variant(Technique::minmax_pcf);
  variant.keys.kernel = 16;
  variant.name = variant_name(variant.technique, variant.keys);
  auto pass = compile_pass(variant, Target::hlsl_dx9, PassKind::query);
  ASSERT_FALSE(pass.ok());
  EXPECT_EQ(pass.error().kind, Error::Kind::bad_input);
  EXPECT_THAT(pass.error().to_string(),
              HasSubstr("variant minmax_pcf_k16, target hlsl_dx9, passes/query.frag"));
  EXPECT_THAT(pass.error().to_string(),
              HasSubstr("minmax_pcf_k16 cannot count exactly on hlsl_dx9: its walk may take 599 "
                        "steps"));
  EXPECT_TRUE(compile_pass(variant, Target::hlsl_dx10, PassKind::query).ok());

  TempDir dir("inexact");
  variant.targets = {Target::spirv};
  ASSERT_TRUE(
      build_library(std::span(&variant, 1), dir.path / "out", {}, ignore_diagnostics()).ok());
  const auto index = dir.path / "out" / "index.json";
  std::string text = slurp(index);
  const std::string spirv = "\"targets\":[\"spirv\"]";
  text.replace(text.find(spirv), spirv.size(), "\"targets\":[\"spirv\",\"hlsl_dx9\"]");
  std::ofstream(index) << text;
  auto loaded = load_library(dir.path / "out");
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().kind, Error::Kind::bad_input);
  EXPECT_THAT(loaded.error().to_string(),
              HasSubstr("/variants/0/targets/1: minmax_pcf_k16 cannot count exactly on hlsl_dx9"));
}

TEST(LoadLibrary, UnknownPassesAndSchemasAreErrorsNamingTheJsonPath) {
  TempDir dir("load");
  const Variant hard = make_variant(Technique::hard);
  ASSERT_TRUE(build_library(std::span(&hard, 1), dir.path / "out", {}, ignore_diagnostics()).ok());
  const auto index = dir.path / "out" / "index.json";
  const std::string text = slurp(index);
  std::string renamed = text;
  renamed.replace(renamed.find("\"query\":{"), 7, "\"blurry\"");
  std::ofstream(index) << renamed;
  auto bad_pass = load_library(dir.path / "out");
  ASSERT_FALSE(bad_pass.ok());
  EXPECT_THAT(bad_pass.error().to_string(), HasSubstr("/variants/0/passes/blurry"));
  std::string schema = text;
  schema.replace(schema.find("\"schema\": 4"), 11, "\"schema\": 3");
  std::ofstream(index) << schema;
  auto bad_schema = load_library(dir.path / "out");
  ASSERT_FALSE(bad_schema.ok());
  EXPECT_EQ(bad_schema.error().kind, Error::Kind::bad_input);
  EXPECT_THAT(bad_schema.error().to_string(), HasSubstr(index.string() + ": /schema"));
  EXPECT_THAT(bad_schema.error().to_string(),
              HasSubstr("index schema 3 is not supported; allowed value 4"));
  std::string sampler = text;
  sampler.replace(sampler.find("\"filter\":\"nearest\""), 18, "\"filter\":\"cubic\"");
  std::ofstream(index) << sampler;
  auto bad_sampler = load_library(dir.path / "out");
  ASSERT_FALSE(bad_sampler.ok());
  EXPECT_THAT(bad_sampler.error().to_string(), HasSubstr("/reflections/"));
  EXPECT_THAT(bad_sampler.error().to_string(), HasSubstr("unknown filter 'cubic'"));
}

// Variants refer to the records of index.json's shared tables by position;
// load_library resolves them into each LibraryVariant.
TEST(LoadLibrary, VariantsSharingAReflectionPointAtOneRecord) {
  TempDir dir("shared");
  Variant k3 = make_variant(Technique::pcf_grid);
  k3.keys.kernel = 3;
  k3.name = variant_name(k3.technique, k3.keys);
  const std::vector<Variant> variants = {make_variant(Technique::pcf_grid), k3,
                                         make_variant(Technique::pcss)};
  ASSERT_TRUE(build_library(variants, dir.path / "out", {}, ignore_diagnostics()).ok());
  const auto index = nlohmann::json::parse(slurp(dir.path / "out" / "index.json"));
  const auto& entries = index.at("variants");
  ASSERT_EQ(entries.size(), 3u);
  std::size_t references = 0;
  for (const auto& entry : entries) {
    for (const auto& [pass, by_target] : entry.at("reflection").items()) {
      references += by_target.size();
      for (const auto& [target, ref] : by_target.items()) {
        EXPECT_LT(ref.get<std::size_t>(), index.at("reflections").size()) << pass << target;
      }
    }
  }
  // Every variant's depth pass, and the two pcf_grid kernels' query passes
  // (they differ only in a constant of the text), are one record per target.
  for (Target target : kAllTargets) {
    const std::string name(to_string(target));
    const auto& depth = entries[0].at("reflection").at("depth").at(name);
    EXPECT_EQ(entries[1].at("reflection").at("depth").at(name), depth) << name;
    EXPECT_EQ(entries[2].at("reflection").at("depth").at(name), depth) << name;
    EXPECT_EQ(entries[1].at("reflection").at("query").at(name),
              entries[0].at("reflection").at("query").at(name))
        << name;
    // The depth pass's files are shared too: one record; the query's are
    // each variant's own.
    EXPECT_EQ(entries[2].at("passes").at("depth").at(name),
              entries[0].at("passes").at("depth").at(name))
        << name;
    EXPECT_NE(entries[1].at("passes").at("query").at(name),
              entries[0].at("passes").at("query").at(name))
        << name;
  }
  EXPECT_LT(index.at("reflections").size(), references);
  // pcss's blocker and PCF disks are whitepaper16 both: one record.
  EXPECT_EQ(index.at("disks").size(), 1u);
  EXPECT_EQ(entries[2].at("disks"), nlohmann::json({{"blocker", 0}, {"pcf", 0}}));
  // The hlsl_dx9 constant textures holding them name the variant's disk.
  const auto& dx9_query =
      index.at("reflections")
          .at(entries[2].at("reflection").at("query").at("hlsl_dx9").get<std::size_t>());
  std::size_t constant_textures = 0;
  for (const auto& texture : dx9_query.at("frag").at("textures")) {
    if (!texture.contains("contents")) continue;
    const std::string disk = texture.at("name") == "pcf_disk" ? "pcf" : "blocker";
    EXPECT_EQ(texture.at("contents"), nlohmann::json({{"disk", disk}})) << texture.at("name");
    ++constant_textures;
  }
  EXPECT_EQ(constant_textures, 2u);
  EXPECT_FALSE(index.contains("texture_contents"));

  auto library = load_library(dir.path / "out");
  ASSERT_TRUE(library.ok()) << library.error().to_string();
  const LibraryVariant* pcss = library->find(variants[2].name);
  ASSERT_NE(pcss, nullptr);
  EXPECT_EQ(pcss->variant.blocker_disk->points, whitepaper16().points);
  EXPECT_EQ(pcss->variant.pcf_disk->points, whitepaper16().points);
  const auto record = [](const LibraryVariant& v, PassKind pass, Target target) {
    return nlohmann::json(v.reflection.at(pass).at(target));
  };
  EXPECT_EQ(record(*pcss, PassKind::depth, Target::spirv),
            record(library->variants[0], PassKind::depth, Target::spirv));
  EXPECT_NE(record(*pcss, PassKind::query, Target::hlsl_dx9),
            record(library->variants[0], PassKind::query, Target::hlsl_dx9));
  EXPECT_EQ(pcss->passes.at(PassKind::depth).at(Target::spirv).frag,
            library->variants[0].passes.at(PassKind::depth).at(Target::spirv).frag);
}

// Two variants that differ only in their disks share every reflection
// record, hlsl_dx9's with its disk textures too; each loaded variant's
// textures hold its own disk.
TEST(LoadLibrary, RecordsThatDifferOnlyInTheirDisksAreOne) {
  TempDir dir("disks");
  Variant other = make_variant(Technique::pcf_poisson);
  other.keys.disk = "blue";
  auto blue = generate_disk({.count = 16, .seed = 7, .method = "best_candidate"});
  ASSERT_TRUE(blue.ok()) << blue.error().to_string();
  other.pcf_disk = *blue;
  other.name = variant_name(other.technique, other.keys);
  const std::vector<Variant> variants = {make_variant(Technique::pcf_poisson), other};
  ASSERT_TRUE(build_library(variants, dir.path / "out", {}, ignore_diagnostics()).ok());
  const auto index = nlohmann::json::parse(slurp(dir.path / "out" / "index.json"));
  const auto& entries = index.at("variants");
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].at("reflection"), entries[1].at("reflection"));
  for (const auto& [target, form] : entries[0].at("function").items()) {
    EXPECT_EQ(entries[1].at("function").at(target).at("reflection"), form.at("reflection"))
        << target;
  }
  EXPECT_NE(entries[0].at("disks"), entries[1].at("disks"));

  auto library = load_library(dir.path / "out");
  ASSERT_TRUE(library.ok()) << library.error().to_string();
  for (const LibraryVariant& loaded : library->variants) {
    const PassReflection& dx9 = loaded.reflection.at(PassKind::query).at(Target::hlsl_dx9);
    const auto texture = std::ranges::find(dx9.frag.textures, "pcf_disk", &TextureBinding::name);
    ASSERT_NE(texture, dx9.frag.textures.end()) << loaded.variant.name;
    EXPECT_EQ(texture->contents, texture_contents(TextureId::pcf_disk, loaded.variant))
        << loaded.variant.name;
  }
  EXPECT_NE(library->variants[0].variant.pcf_disk->points,
            library->variants[1].variant.pcf_disk->points);
}

// Loads the library at `root` with `index` written as its index.json after
// setting `pointer` to `value`: the bad_input error's text, or "loaded".
std::string load_with(const std::filesystem::path& root, const nlohmann::json& index,
                      const std::string& pointer, const nlohmann::json& value) {
  nlohmann::json broken = index;
  broken[nlohmann::json::json_pointer(pointer)] = value;
  std::ofstream(root / "index.json") << broken.dump(2);
  auto library = load_library(root);
  if (library.ok()) return std::string("loaded");
  EXPECT_EQ(library.error().kind, Error::Kind::bad_input);
  return library.error().to_string();
}

TEST(LoadLibrary, ReferencesOutOfRangeAreErrorsNamingTheJsonPath) {
  TempDir dir("badref");
  const Variant pcss = make_variant(Technique::pcss);
  ASSERT_TRUE(build_library(std::span(&pcss, 1), dir.path / "out", {}, ignore_diagnostics()).ok());
  const auto file = dir.path / "out" / "index.json";
  const auto index = nlohmann::json::parse(slurp(file));
  const auto refused = [&](const std::string& pointer, const nlohmann::json& value) {
    return load_with(dir.path / "out", index, pointer, value);
  };
  const std::size_t records = index.at("reflections").size();
  EXPECT_THAT(refused("/variants/0/reflection/query/spirv", records),
              HasSubstr(file.string() + ": /variants/0/reflection/query/spirv: reference " +
                        std::to_string(records) + " is out of range; allowed 0.." +
                        std::to_string(records - 1) + ", positions in /reflections"));
  EXPECT_THAT(refused("/variants/0/reflection/depth/glsl330", -1),
              HasSubstr("/variants/0/reflection/depth/glsl330: reference -1 is out of range"));
  EXPECT_THAT(refused("/variants/0/reflection/depth/glsl330", "0"),
              HasSubstr("/variants/0/reflection/depth/glsl330: reference \"0\" is out of range"));
  EXPECT_THAT(refused("/variants/0/passes/depth/spirv", 1.5),
              HasSubstr(": /variants/0/passes/depth/spirv: reference 1.5 is out of range; "
                        "allowed 0.."));
  EXPECT_THAT(refused("/variants/0/disks/pcf", 1),
              HasSubstr(": /variants/0/disks/pcf: reference 1 is out of range; allowed 0..0, "
                        "positions in /disks"));
  const std::size_t dx9_query =
      index.at("variants").at(0).at("reflection").at("query").at("hlsl_dx9").get<std::size_t>();
  const auto& textures = index.at("reflections").at(dx9_query).at("frag").at("textures");
  for (std::size_t t = 0; t < textures.size(); ++t) {
    if (!textures[t].contains("contents")) continue;
    const std::string pointer = "/reflections/" + std::to_string(dx9_query) + "/frag/textures/" +
                                std::to_string(t) + "/contents";
    const std::string disk = textures[t].at("name") == "pcf_disk" ? "pcf" : "blocker";
    EXPECT_THAT(refused(pointer, 2),
                HasSubstr(": " + pointer + ": expected {\"disk\": \"" + disk + "\"}, got 2"));
    EXPECT_THAT(refused(pointer, {{"disk", "other"}}),
                HasSubstr(": " + pointer + ": expected {\"disk\": \"" + disk + "\"}"));
    break;
  }
  nlohmann::json no_disk = index;
  no_disk.at("variants").at(0).at("disks").erase("pcf");
  std::ofstream(file) << no_disk.dump(2);
  auto diskless = load_library(dir.path / "out");
  ASSERT_FALSE(diskless.ok());
  EXPECT_THAT(diskless.error().to_string(),
              HasSubstr("'s texture 'pcf_disk' holds the pcf disk, and this variant has none in "
                        "its /disks"));
  nlohmann::json no_record = index;
  no_record.at("variants").at(0).at("reflection").at("query").erase("essl300");
  std::ofstream(file) << no_record.dump(2);
  auto missing = load_library(dir.path / "out");
  ASSERT_FALSE(missing.ok());
  EXPECT_THAT(missing.error().to_string(), HasSubstr("/variants/0/reflection/query/essl300"));
}

// A disk point or blur weight out of range (NaN cannot be written in JSON;
// 1e39 is beyond float's range) is refused naming its JSON path.
TEST(LoadLibrary, DiskPointsAndBlurWeightsOutOfRangeAreErrorsNamingTheJsonPath) {
  TempDir dir("badvalues");
  const Variant variants[] = {make_variant(Technique::pcss), make_variant(Technique::screen_blur)};
  ASSERT_TRUE(build_library(std::span(variants), dir.path / "out", {}, ignore_diagnostics()).ok());
  const auto file = dir.path / "out" / "index.json";
  const auto index = nlohmann::json::parse(slurp(file));
  const auto refused = [&](const std::string& pointer, const nlohmann::json& value) {
    return load_with(dir.path / "out", index, pointer, value);
  };
  for (const nlohmann::json& value : {nlohmann::json(1e39), nlohmann::json(-2.5)}) {
    EXPECT_EQ(refused("/disks/0/points/3/1", value),
              file.string() +
                  ": /disks/0/points/3: out of range; allowed: coordinates from -1 to 1 "
                  "(a unit disk)")
        << value;
  }
  std::size_t blur = 0;
  while (index.at("variants").at(blur).at("technique") != "screen_blur") ++blur;
  const std::string weight = "/variants/" + std::to_string(blur) + "/blur_weights/2";
  for (const nlohmann::json& value : {nlohmann::json(1e39), nlohmann::json(-0.5)}) {
    EXPECT_EQ(refused(weight, value),
              file.string() + ": " + weight + ": out of range; allowed: a weight from 0 to 1")
        << value;
  }
}

// Schema 2 repeated every variant's pass files, reflection records and
// disks, each nested member on a line of its own: 2,620,995 bytes for the
// default library's 33 variants (with bytecode), against about 0.21 MB for
// them in schema 3, 0.55 MB for 60 variants with their deferred passes,
// 0.61 MB for 76, 0.71 MB for the same 76 once minmax_pcf and pcss_minmax
// have deferred passes and function forms, and 0.73 MB once the
// back-projections have them too. Schema 4 shares hlsl_dx9's records across
// disks: 0.56 MB without bytecode, as built here (0.67 MB with it); 0.70 MB
// for the 81 with the atlas variants, 0.77 MB for 84 with the array ones,
// 0.78 MB for 85.
TEST(BuildLibrary, DefaultLibraryIndexStaysSmall) {
  TempDir dir("default");
  auto variants =
      load_variants(std::filesystem::path(PENUMBRA_SOURCE_DIR) / "permutations" / "default.json");
  ASSERT_TRUE(variants.ok()) << variants.error().to_string();
  ASSERT_TRUE(build_library(*variants, dir.path / "out", {.jobs = 2}, ignore_diagnostics()).ok());
  EXPECT_LT(std::filesystem::file_size(dir.path / "out" / "index.json"), 800'000u);
  ASSERT_TRUE(load_library(dir.path / "out").ok());
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
  // Per target 4 shared files (the depth pass's two stages, the query's
  // and the deferred pass's vertex stages) and each variant's query and
  // deferred fragment stages; per text target each variant's function form;
  // and the index.
  const auto text_targets =
      std::ranges::count_if(kAllTargets, [](Target target) { return traits(target).is_text; });
  EXPECT_EQ(files, kAllTargets.size() * (4u + 2u * 2u) + 2u * std::size_t(text_targets) + 1u);
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
  const std::string text = slurp(dir.path / "out" / "hlsl_dx10" / v.name / "query.frag.hlsl");
  EXPECT_THAT(text.substr(0, 200),
              HasSubstr("Variant " + v.name + " (technique pcss, blocker_samples 25"));
  // Two different disks keep their own source names.
  EXPECT_THAT(text, HasSubstr("BLOCKER_DISK[25]"));
  EXPECT_THAT(text, HasSubstr("PCF_DISK[16]"));
  // hlsl_dx9 reads them from constant textures whose reflection holds the
  // same values, point i at texel (i, 0).
  const auto& textures = loaded->reflection.at(PassKind::query).at(Target::hlsl_dx9).frag.textures;
  for (const auto& [name, disk] :
       {std::pair{"blocker_disk", *v.blocker_disk}, std::pair{"pcf_disk", *v.pcf_disk}}) {
    const auto texture = std::ranges::find(textures, std::string(name), &TextureBinding::name);
    ASSERT_NE(texture, textures.end()) << name;
    ASSERT_TRUE(texture->contents.has_value()) << name;
    EXPECT_EQ(texture->contents->width, disk.points.size()) << name;
    EXPECT_EQ(texture->contents->height, 1u) << name;
    std::vector<float> texels;
    for (const Point2& point : disk.points) texels.insert(texels.end(), point.begin(), point.end());
    EXPECT_EQ(texture->contents->texels, texels) << name;
  }
  EXPECT_THAT(slurp(dir.path / "out" / "hlsl_dx9" / v.name / "query.frag.hlsl"),
              Not(HasSubstr("PCF_DISK")));
}

TEST(BuildLibrary, MinmaxPassesOnlyForTheVariantsThatUseThem) {
  TempDir dir("minmax");
  const std::vector<Variant> variants = {make_variant(Technique::hard),
                                         make_variant(Technique::backprojection)};
  ASSERT_TRUE(build_library(variants, dir.path / "out", {.jobs = 2}, ignore_diagnostics()).ok());
  for (Target target : kAllTargets) {
    for (const char* stem : {"minmax_init", "minmax_reduce"}) {
      for (ShaderStage stage : {ShaderStage::vertex, ShaderStage::fragment}) {
        const auto path = dir.path / "out" / std::string(to_string(target)) / "common" /
                          output_file_name(target, stem, stage);
        EXPECT_TRUE(std::filesystem::exists(path)) << path;
      }
    }
  }
  auto library = load_library(dir.path / "out");
  ASSERT_TRUE(library.ok()) << library.error().to_string();
  const LibraryVariant* hard = library->find("hard");
  const LibraryVariant* back = library->find("backprojection");
  ASSERT_TRUE(hard && back);
  EXPECT_FALSE(hard->passes.contains(PassKind::minmax_init));
  EXPECT_FALSE(hard->passes.contains(PassKind::minmax_reduce));
  ASSERT_TRUE(back->passes.contains(PassKind::minmax_reduce));
  EXPECT_EQ(back->passes.at(PassKind::minmax_reduce).at(Target::glsl330).vert,
            "glsl330/common/minmax_reduce.vert");
  EXPECT_EQ(back->passes.at(PassKind::minmax_init).at(Target::hlsl_dx9).frag,
            "hlsl_dx9/common/minmax_init.frag.hlsl");
  EXPECT_THAT(slurp(dir.path / "out" / "glsl450" / "common" / "minmax_init.vert"),
              HasSubstr("Shared by every variant that reads the min-max mip; target glsl450; "
                        "minmax_init pass, vertex stage"));
}

TEST(BuildLibrary, ScreenBlurPassesAndWeightsInTheIndex) {
  TempDir dir("blur");
  const std::vector<Variant> variants = {make_variant(Technique::hard),
                                         make_variant(Technique::screen_blur), depth_aware_blur()};
  ASSERT_TRUE(build_library(variants, dir.path / "out", {.jobs = 2}, ignore_diagnostics()).ok());
  auto library = load_library(dir.path / "out");
  ASSERT_TRUE(library.ok()) << library.error().to_string();
  const LibraryVariant* hard = library->find("hard");
  const LibraryVariant* blur = library->find("screen_blur_r4");
  const LibraryVariant* aware = library->find("screen_blur_r4_depth_aware");
  ASSERT_TRUE(hard && blur && aware);
  for (PassKind kind : {PassKind::blur_h, PassKind::blur_v, PassKind::composite}) {
    EXPECT_FALSE(hard->passes.contains(kind));
    EXPECT_TRUE(blur->passes.contains(kind));
  }
  for (PassKind kind : {PassKind::minmax_init, PassKind::minmax_reduce}) {
    EXPECT_FALSE(blur->passes.contains(kind));
  }
  EXPECT_EQ(blur->passes.at(PassKind::blur_h).at(Target::hlsl_dx9).frag,
            "hlsl_dx9/screen_blur_r4/blur_h.frag.hlsl");
  EXPECT_EQ(aware->passes.at(PassKind::blur_v).at(Target::spirv).frag,
            "spirv/screen_blur_r4_depth_aware/blur_v.frag.spv");
  EXPECT_EQ(blur->passes.at(PassKind::blur_v).at(Target::glsl330).vert,
            "glsl330/common/blur_v.vert");
  EXPECT_EQ(aware->passes.at(PassKind::composite).at(Target::essl300).frag,
            "essl300/common/composite.frag");
  EXPECT_EQ(aware->passes.at(PassKind::query).at(Target::spirv).frag,
            "spirv/screen_blur_r4_depth_aware/query.frag.spv");
  // Keys and weights come back exactly; the bool key too.
  EXPECT_EQ(blur->variant.keys.blur_radius, 4);
  EXPECT_FALSE(blur->variant.keys.depth_aware.has_value());
  EXPECT_EQ(aware->variant.keys.depth_aware, true);
  EXPECT_EQ(blur->variant.blur_weights, gaussian_weights(4));
  EXPECT_EQ(aware->variant.blur_weights, gaussian_weights(4));
  EXPECT_TRUE(hard->variant.blur_weights.empty());
  const auto index = nlohmann::json::parse(slurp(dir.path / "out" / "index.json"));
  for (const auto& entry : index.at("variants")) {
    const bool blurs = entry.at("technique") == "screen_blur";
    EXPECT_EQ(entry.contains("blur_weights"), blurs) << entry.at("name");
    EXPECT_EQ(entry.at("passes").contains("composite"), blurs) << entry.at("name");
  }
  EXPECT_EQ(index.at("variants").at(2).at("keys").at("depth_aware"), true);
  EXPECT_EQ(index.at("variants").at(2).at("blur_weights").size(), 9u);
  EXPECT_THAT(slurp(dir.path / "out" / "glsl450" / "common" / "composite.frag"),
              HasSubstr("Shared by every screen_blur variant; target glsl450; composite pass"));
}

TEST(BuildLibrary, NoScreenBlurPassesWithoutAScreenBlurVariant) {
  TempDir dir("no-blur");
  const Variant hard = make_variant(Technique::hard);
  ASSERT_TRUE(build_library(std::span(&hard, 1), dir.path / "out", {}, ignore_diagnostics()).ok());
  for (const char* file : {"composite.frag.spv", "blur_h.vert.spv", "blur_v.vert.spv"}) {
    EXPECT_FALSE(std::filesystem::exists(dir.path / "out" / "spirv" / "common" / file)) << file;
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path / "out" / "spirv" / "hard" / "blur_h.frag.spv"));
}

TEST(BuildLibrary, NoMinmaxPassesWithoutAVariantThatUsesThem) {
  TempDir dir("no-minmax");
  const Variant hard = make_variant(Technique::hard);
  ASSERT_TRUE(build_library(std::span(&hard, 1), dir.path / "out", {}, ignore_diagnostics()).ok());
  EXPECT_TRUE(std::filesystem::exists(dir.path / "out" / "spirv" / "common" / "depth.frag.spv"));
  EXPECT_FALSE(
      std::filesystem::exists(dir.path / "out" / "spirv" / "common" / "minmax_init.frag.spv"));
}

}  // namespace
}  // namespace penumbra
