// Manifest expansion: the default library, disks, exclusions, merging, order.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "penumbra/compiler/disk.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/model/shader_contract.hpp"

namespace penumbra {
namespace {

const std::vector<Target> kEveryTarget(kAllTargets.begin(), kAllTargets.end());

std::vector<Variant> expand_text(std::string_view json) {
  Result<Manifest> manifest = parse_manifest(json, "test.json");
  EXPECT_TRUE(manifest.ok()) << manifest.error().to_string();
  if (!manifest) return {};
  Result<std::vector<Variant>> variants = expand(*manifest);
  EXPECT_TRUE(variants.ok()) << variants.error().to_string();
  return variants ? *variants : std::vector<Variant>{};
}

std::vector<std::string> names(const std::vector<Variant>& variants) {
  std::vector<std::string> out;
  for (const Variant& variant : variants) out.push_back(variant.name);
  return out;
}

const Variant* find(const std::vector<Variant>& variants, std::string_view name) {
  for (const Variant& variant : variants) {
    if (variant.name == name) return &variant;
  }
  return nullptr;
}

std::vector<Point2> prefix(const Disk& disk, std::size_t count) {
  return {disk.points.begin(), disk.points.begin() + static_cast<std::ptrdiff_t>(count)};
}

TEST(ManifestExpand, DefaultLibrary) {
  Result<Manifest> manifest = load_manifest(PENUMBRA_SOURCE_DIR "/permutations/default.json");
  ASSERT_TRUE(manifest.ok()) << manifest.error().to_string();
  Result<std::vector<Variant>> variants = expand(*manifest);
  ASSERT_TRUE(variants.ok()) << variants.error().to_string();
  EXPECT_EQ(names(*variants), (std::vector<std::string>{
                                  "hard",
                                  "hard_array",
                                  "hard_atlas",
                                  "hard_orthographic",
                                  "hard_perspective",
                                  "hard_perspective_reversed",
                                  "pcf_grid_k3",
                                  "pcf_grid_k3_array",
                                  "pcf_grid_k3_atlas",
                                  "pcf_grid_k3_orthographic",
                                  "pcf_grid_k3_perspective",
                                  "pcf_grid_k3_perspective_reversed",
                                  "pcf_grid_k5",
                                  "pcf_grid_k7",
                                  "pcf_poisson_p16_poisson",
                                  "pcf_poisson_p16_poisson_orthographic",
                                  "pcf_poisson_p16_poisson_perspective",
                                  "pcf_poisson_p16_poisson_perspective_reversed",
                                  "pcf_poisson_p16_poisson_receiver_plane",
                                  "pcf_poisson_p16_poisson_ign",
                                  "pcf_poisson_p16_poisson_ign_atlas",
                                  "pcf_poisson_p16_square",
                                  "pcf_poisson_p16_whitepaper16",
                                  "pcf_poisson_p25_poisson",
                                  "pcf_poisson_p32_poisson",
                                  "pcf_poisson_p64_poisson",
                                  "pcss_b16_p16_poisson",
                                  "pcss_b16_p16_poisson_orthographic",
                                  "pcss_b16_p16_poisson_perspective",
                                  "pcss_b16_p16_poisson_perspective_reversed",
                                  "pcss_b16_p16_poisson_receiver_plane",
                                  "pcss_b16_p16_poisson_receiver_plane_orthographic_array",
                                  "pcss_b16_p16_poisson_receiver_plane_orthographic_atlas",
                                  "pcss_b16_p16_poisson_receiver_plane_perspective_reversed_array",
                                  "pcss_b16_p16_poisson_receiver_plane_perspective_reversed_atlas",
                                  "pcss_b16_p16_poisson_ign",
                                  "pcss_b16_p16_square",
                                  "pcss_b16_p16_whitepaper16",
                                  "pcss_b16_p25_poisson",
                                  "pcss_b16_p32_poisson",
                                  "pcss_b16_p32_square",
                                  "pcss_b16_p64_poisson",
                                  "pcss_b16_p64_square",
                                  "pcss_b25_p16_poisson",
                                  "pcss_b25_p16_square",
                                  "pcss_b25_p25_poisson",
                                  "pcss_b25_p32_poisson",
                                  "pcss_b25_p32_square",
                                  "pcss_b25_p64_poisson",
                                  "pcss_b25_p64_square",
                                  "pcss_b25_p64_square_receiver_plane",
                                  "pcss_b25_p64_square_ign",
                                  "pcss_b32_p16_poisson",
                                  "pcss_b32_p25_poisson",
                                  "pcss_b32_p32_poisson",
                                  "pcss_b32_p64_poisson",
                                  "minmax_pcf_k8",
                                  "minmax_pcf_k8_orthographic",
                                  "minmax_pcf_k8_perspective",
                                  "minmax_pcf_k8_perspective_reversed",
                                  "minmax_pcf_k16",
                                  "minmax_pcf_k32",
                                  "minmax_pcf_k64",
                                  "backprojection",
                                  "backprojection_orthographic",
                                  "backprojection_perspective",
                                  "backprojection_perspective_reversed",
                                  "pcss_minmax_p16_poisson",
                                  "pcss_minmax_p16_poisson_orthographic",
                                  "pcss_minmax_p16_poisson_perspective",
                                  "pcss_minmax_p16_poisson_perspective_reversed",
                                  "pcss_minmax_p32_poisson",
                                  "pcss_minmax_p32_poisson_ign",
                                  "pcss_minmax_p32_square",
                                  "pcss_minmax_p32_square_ign",
                                  "screen_blur_r2",
                                  "screen_blur_r4",
                                  "screen_blur_r4_depth_aware",
                                  "screen_blur_r8",
                                  "bitmask_backprojection_bits64",
                                  "bitmask_backprojection_bits64_orthographic",
                                  "bitmask_backprojection_bits64_perspective",
                                  "bitmask_backprojection_bits64_perspective_reversed",
                                  "bitmask_backprojection_bits256",
                                  "bitmask_backprojection_bits1024",
                              }));
  // Every target, but hlsl_dx9 has no integer bit operations for the bitmask
  // and cannot count minmax_pcf's larger kernels exactly.
  for (const Variant& variant : *variants) {
    std::vector<Target> expected = kEveryTarget;
    std::erase_if(expected, [&](Target target) { return !can_emit(variant, target); });
    EXPECT_EQ(variant.targets, expected) << variant.name;
  }
  EXPECT_EQ(find(*variants, "minmax_pcf_k8")->targets, kEveryTarget);
  EXPECT_EQ(find(*variants, "minmax_pcf_k16")->targets.size(), kEveryTarget.size() - 1);

  const Variant* whitepaper = find(*variants, "pcss_b16_p16_whitepaper16");
  ASSERT_TRUE(whitepaper && whitepaper->blocker_disk && whitepaper->pcf_disk);
  EXPECT_EQ(whitepaper->blocker_disk->points, whitepaper16().points);
  EXPECT_EQ(whitepaper->pcf_disk->points, whitepaper16().points);

  const Variant* minmax = find(*variants, "pcss_minmax_p32_poisson");
  ASSERT_TRUE(minmax && minmax->pcf_disk);
  EXPECT_FALSE(minmax->blocker_disk.has_value());
  EXPECT_EQ(minmax->pcf_disk->points,
            generate_disk({.count = 32, .seed = 1, .method = "sample_elimination"})->points);

  const Variant* blur = find(*variants, "screen_blur_r4_depth_aware");
  ASSERT_TRUE(blur);
  EXPECT_EQ(blur->keys.blur_radius, 4);
  EXPECT_EQ(blur->keys.depth_aware, true);
  EXPECT_EQ(blur->blur_weights, gaussian_weights(4));
  for (const Variant& variant : *variants) {
    EXPECT_EQ(variant.blur_weights.empty(), variant.technique != Technique::screen_blur)
        << variant.name;
  }

  const Variant* generated = find(*variants, "pcss_b32_p64_poisson");
  ASSERT_TRUE(generated && generated->blocker_disk && generated->pcf_disk);
  EXPECT_EQ(generated->pcf_disk->name, "poisson");
  EXPECT_EQ(generated->blocker_disk->points,
            generate_disk({.count = 32, .seed = 1, .method = "sample_elimination"})->points);
  EXPECT_EQ(generated->pcf_disk->points,
            generate_disk({.count = 64, .seed = 1, .method = "sample_elimination"})->points);
}

TEST(ManifestExpand, VariantsCarryTheirKeysAndDisks) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1,
    "disks": {"poisson": {"method": "best_candidate", "seed": 9}},
    "sets": [{"technique": ["hard", "pcf_grid", "pcss"], "kernel": 5, "blocker_samples": 12,
              "pcf_samples": 8, "disk": ["poisson", "whitepaper16"]}]})");
  ASSERT_EQ(names(variants), (std::vector<std::string>{"hard", "pcf_grid_k5", "pcss_b12_p8_poisson",
                                                       "pcss_b12_p8_whitepaper16"}));
  EXPECT_FALSE(variants[0].keys.kernel.has_value());
  EXPECT_FALSE(variants[0].pcf_disk.has_value());
  EXPECT_EQ(variants[1].keys.kernel, 5);
  EXPECT_FALSE(variants[1].keys.disk.has_value());

  const Variant& generated = variants[2];
  EXPECT_EQ(generated.keys.blocker_samples, 12);
  EXPECT_EQ(generated.keys.pcf_samples, 8);
  EXPECT_EQ(generated.keys.disk, "poisson");
  ASSERT_TRUE(generated.blocker_disk && generated.pcf_disk);
  EXPECT_EQ(generated.blocker_disk->name, "poisson");
  EXPECT_EQ(generated.blocker_disk->method, "best_candidate");
  EXPECT_EQ(generated.blocker_disk->seed, 9u);
  EXPECT_EQ(generated.blocker_disk->points,
            generate_disk({.count = 12, .seed = 9, .method = "best_candidate"})->points);
  EXPECT_EQ(generated.pcf_disk->points,
            generate_disk({.count = 8, .seed = 9, .method = "best_candidate"})->points);

  // whitepaper16 serves smaller counts as a prefix.
  const Variant& whitepaper = variants[3];
  ASSERT_TRUE(whitepaper.blocker_disk && whitepaper.pcf_disk);
  EXPECT_EQ(whitepaper.pcf_disk->name, "whitepaper16");
  EXPECT_EQ(whitepaper.blocker_disk->points, prefix(whitepaper16(), 12));
  EXPECT_EQ(whitepaper.pcf_disk->points, prefix(whitepaper16(), 8));
}

TEST(ManifestExpand, Whitepaper16PrefixesForBothDisks) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1, "sets": [
    {"technique": "pcss", "blocker_samples": 16, "pcf_samples": 9, "disk": "whitepaper16"}]})");
  ASSERT_EQ(names(variants), std::vector<std::string>{"pcss_b16_p9_whitepaper16"});
  EXPECT_EQ(variants[0].blocker_disk->points, whitepaper16().points);
  EXPECT_EQ(variants[0].pcf_disk->points, prefix(whitepaper16(), 9));
  EXPECT_EQ(variants[0].pcf_disk->normalized_min_distance,
            normalized_min_distance(prefix(whitepaper16(), 9)));
}

TEST(ManifestExpand, ExclusionWithTargetRemovesOnlyThatTarget) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1,
    "disks": {"poisson": {}},
    "sets": [{"technique": "pcss", "blocker_samples": 16, "pcf_samples": [16, 64],
              "disk": "poisson"}],
    "exclude": [{"technique": "pcss", "pcf_samples": 64, "target": "hlsl_dx9"}]})");
  ASSERT_EQ(names(variants),
            (std::vector<std::string>{"pcss_b16_p16_poisson", "pcss_b16_p64_poisson"}));
  EXPECT_EQ(variants[0].targets, kEveryTarget);
  EXPECT_EQ(variants[1].targets,
            (std::vector<Target>{Target::spirv, Target::glsl450, Target::glsl330, Target::essl300,
                                 Target::hlsl_dx11, Target::hlsl_dx10}));
}

TEST(ManifestExpand, ExclusionWithoutTargetDropsTheVariant) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1,
    "sets": [{"technique": "pcf_grid", "kernel": [3, 5, 7, 9]}],
    "exclude": [{"kernel": [5, 9]}]})");
  EXPECT_EQ(names(variants), (std::vector<std::string>{"pcf_grid_k3", "pcf_grid_k7"}));
}

TEST(ManifestExpand, TargetOnlyExclusionAppliesToEveryVariant) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1,
    "targets": ["spirv", "hlsl_dx9"],
    "sets": [{"technique": ["hard", "pcf_grid"], "kernel": 3}],
    "exclude": [{"target": "hlsl_dx9"}]})");
  ASSERT_EQ(names(variants), (std::vector<std::string>{"hard", "pcf_grid_k3"}));
  for (const Variant& variant : variants) {
    EXPECT_EQ(variant.targets, std::vector<Target>{Target::spirv}) << variant.name;
  }
}

TEST(ManifestExpand, VariantLeftWithoutTargetsIsDropped) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1,
    "targets": ["glsl330", "essl300"],
    "sets": [{"technique": ["hard", "pcf_grid"], "kernel": 3}],
    "exclude": [{"technique": "pcf_grid", "target": "glsl330"},
                {"technique": "pcf_grid", "target": ["essl300"]}]})");
  EXPECT_EQ(names(variants), std::vector<std::string>{"hard"});
}

TEST(ManifestExpand, ExclusionKeyTheVariantLacksDoesNotMatch) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1,
    "sets": [{"technique": ["hard", "pcf_grid"], "kernel": 3}],
    "exclude": [{"kernel": 3}]})");
  EXPECT_EQ(names(variants), std::vector<std::string>{"hard"});
}

// Repeats are merged when read, so they never multiply a set's product.
TEST(ManifestExpand, RepeatedAxisValuesCountOnce) {
  Result<Manifest> manifest = parse_manifest(R"({"schema": 1,
    "sets": [{"technique": ["pcf_grid", "pcf_grid"], "kernel": [3, 3, 5, 3],
              "target": ["spirv", "spirv"]}]})",
                                             "test.json");
  ASSERT_TRUE(manifest.ok()) << manifest.error().to_string();
  const AxisValues& axes = manifest->sets[0].axes;
  EXPECT_EQ(axes.technique, std::vector<Technique>{Technique::pcf_grid});
  EXPECT_EQ(axes.kernel, (std::vector<int>{3, 5}));
  EXPECT_EQ(axes.target, std::vector<Target>{Target::spirv});
}

TEST(ManifestExpand, DuplicatesMergeWithTheUnionOfTargets) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1,
    "sets": [{"technique": "pcf_grid", "kernel": [3, 5], "target": ["hlsl_dx9", "spirv"]},
             {"technique": "pcf_grid", "kernel": 3, "target": ["glsl330", "spirv"]}]})");
  ASSERT_EQ(names(variants), (std::vector<std::string>{"pcf_grid_k3", "pcf_grid_k5"}));
  EXPECT_EQ(variants[0].targets,
            (std::vector<Target>{Target::spirv, Target::glsl330, Target::hlsl_dx9}));
  EXPECT_EQ(variants[1].targets, (std::vector<Target>{Target::spirv, Target::hlsl_dx9}));
}

TEST(ManifestExpand, EveryFormItsTechniqueHasByDefault) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1,
    "sets": [{"technique": ["hard", "backprojection", "screen_blur"], "blur_radius": 2}]})");
  ASSERT_EQ(names(variants),
            (std::vector<std::string>{"hard", "backprojection", "screen_blur_r2"}));
  const std::vector<Form> all = {Form::query, Form::deferred, Form::function};
  EXPECT_EQ(variants[0].forms, all);
  EXPECT_EQ(variants[1].forms, all);
  EXPECT_EQ(variants[2].forms, std::vector<Form>{Form::query});  // screen_blur has no other
}

// A set's forms replace the top-level ones; a variant several sets give is
// built in the union of their forms, in kAllForms order.
TEST(ManifestExpand, FormsOfASetAndTheUnionOfDuplicates) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1, "forms": ["query"],
    "sets": [{"technique": "pcf_grid", "kernel": [3, 5], "forms": ["function"]},
             {"technique": "pcf_grid", "kernel": 3, "forms": "deferred"},
             {"technique": ["hard", "screen_blur"], "blur_radius": 1,
              "forms": ["function", "query"]},
             {"technique": "pcss", "blocker_samples": 16, "pcf_samples": 16,
              "disk": "whitepaper16"}]})");
  ASSERT_EQ(names(variants),
            (std::vector<std::string>{"hard", "pcf_grid_k3", "pcf_grid_k5",
                                      "pcss_b16_p16_whitepaper16", "screen_blur_r1"}));
  EXPECT_EQ(variants[0].forms, (std::vector<Form>{Form::query, Form::function}));
  EXPECT_EQ(variants[1].forms, (std::vector<Form>{Form::deferred, Form::function}));
  EXPECT_EQ(variants[2].forms, std::vector<Form>{Form::function});
  EXPECT_EQ(variants[3].forms, std::vector<Form>{Form::query});
  EXPECT_EQ(variants[4].forms, std::vector<Form>{Form::query});  // screen_blur has no function form
}

TEST(ManifestExpand, SortsByTechniqueThenNumericKeys) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1,
    "disks": {"b": {"seed": 2}, "a": {"seed": 3}},
    "sets": [{"technique": "pcss", "blocker_samples": [25, 9], "pcf_samples": [100, 16],
              "disk": ["b", "a"]},
             {"technique": "pcf_grid", "kernel": [11, 3, 7]},
             {"technique": "hard"}]})");
  EXPECT_EQ(names(variants),
            (std::vector<std::string>{"hard", "pcf_grid_k3", "pcf_grid_k7", "pcf_grid_k11",
                                      "pcss_b9_p16_a", "pcss_b9_p16_b", "pcss_b9_p100_a",
                                      "pcss_b9_p100_b", "pcss_b25_p16_a", "pcss_b25_p16_b",
                                      "pcss_b25_p100_a", "pcss_b25_p100_b"}));
}

TEST(ManifestExpand, TraversalAndMaxNodesAreOptionalAxes) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1,
    "sets": [{"technique": ["minmax_pcf", "pcf_grid"], "kernel": 3},
             {"technique": "minmax_pcf", "kernel": 6},
             {"technique": ["minmax_pcf", "backprojection"], "kernel": 3,
              "traversal": "brute_force"},
             {"technique": "backprojection", "max_nodes": [4096, 64]},
             {"technique": "backprojection"}]})");
  EXPECT_EQ(names(variants),
            (std::vector<std::string>{"pcf_grid_k3", "minmax_pcf_k3", "minmax_pcf_k3_brute_force",
                                      "minmax_pcf_k6", "backprojection", "backprojection_n64",
                                      "backprojection_n4096", "backprojection_brute_force"}));
  const Variant* brute = find(variants, "backprojection_brute_force");
  ASSERT_TRUE(brute);
  EXPECT_EQ(brute->keys.traversal, "brute_force");
  EXPECT_FALSE(brute->keys.kernel.has_value());
  EXPECT_FALSE(brute->keys.max_nodes.has_value());
  const Variant* bounded = find(variants, "backprojection_n64");
  ASSERT_TRUE(bounded);
  EXPECT_EQ(bounded->keys.max_nodes, 64);
  EXPECT_FALSE(bounded->keys.traversal.has_value());
}

TEST(ManifestExpand, ExclusionsMatchTraversalAndMaxNodes) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1,
    "sets": [{"technique": "backprojection", "traversal": "brute_force"},
             {"technique": "backprojection", "max_nodes": [64, 128]},
             {"technique": "backprojection"}],
    "exclude": [{"max_nodes": 64}, {"traversal": "brute_force", "target": "hlsl_dx9"}]})");
  ASSERT_EQ(names(variants), (std::vector<std::string>{"backprojection", "backprojection_n128",
                                                       "backprojection_brute_force"}));
  EXPECT_EQ(variants[1].targets, kEveryTarget);
  EXPECT_EQ(variants[2].targets,
            (std::vector<Target>{Target::spirv, Target::glsl450, Target::glsl330, Target::essl300,
                                 Target::hlsl_dx11, Target::hlsl_dx10}));
}

TEST(ManifestExpand, ScreenBlurKeysAndWeights) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1,
    "sets": [{"technique": "screen_blur", "blur_radius": [8, 1], "depth_aware": [true, false]},
             {"technique": "screen_blur", "blur_radius": 1}]})");
  ASSERT_EQ(names(variants),
            (std::vector<std::string>{"screen_blur_r1", "screen_blur_r1_depth_aware",
                                      "screen_blur_r8", "screen_blur_r8_depth_aware"}));
  // depth_aware false is the default: the key stays unset, so it merges with
  // the set that leaves it out.
  EXPECT_EQ(variants[0].keys.blur_radius, 1);
  EXPECT_FALSE(variants[0].keys.depth_aware.has_value());
  EXPECT_EQ(variants[1].keys.depth_aware, true);
  EXPECT_EQ(variants[0].blur_weights, gaussian_weights(1));
  EXPECT_EQ(variants[3].blur_weights, gaussian_weights(8));
  EXPECT_EQ(variants[3].blur_weights.size(), 17u);
}

TEST(ManifestExpand, ExclusionsMatchBlurRadiusAndDepthAware) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1,
    "sets": [{"technique": ["screen_blur", "hard"], "blur_radius": [2, 4],
              "depth_aware": [false, true]}],
    "exclude": [{"blur_radius": 2, "depth_aware": true},
                {"depth_aware": false, "target": "hlsl_dx9"}]})");
  ASSERT_EQ(names(variants), (std::vector<std::string>{"hard", "screen_blur_r2", "screen_blur_r4",
                                                       "screen_blur_r4_depth_aware"}));
  // A key the variant lacks never matches: hard keeps every target.
  EXPECT_EQ(variants[0].targets, kEveryTarget);
  const std::vector<Target> no_dx9{Target::spirv,   Target::glsl450,   Target::glsl330,
                                   Target::essl300, Target::hlsl_dx11, Target::hlsl_dx10};
  EXPECT_EQ(variants[1].targets, no_dx9);
  EXPECT_EQ(variants[2].targets, no_dx9);
  EXPECT_EQ(variants[3].targets, kEveryTarget);
}

// receiver_plane is a flag like depth_aware: false leaves the key unset, and
// an exclusion's false matches the variants without it.
TEST(ManifestExpand, ReceiverPlaneFalseIsTheDefault) {
  const std::vector<Variant> variants = expand_text(R"({"schema": 1,
    "sets": [{"technique": "pcf_poisson", "pcf_samples": 16, "disk": "whitepaper16",
              "receiver_plane": [false, true], "rotation": "ign"}],
    "exclude": [{"receiver_plane": false, "target": "hlsl_dx9"}]})");
  ASSERT_EQ(names(variants),
            (std::vector<std::string>{"pcf_poisson_p16_whitepaper16_ign",
                                      "pcf_poisson_p16_whitepaper16_ign_receiver_plane"}));
  EXPECT_FALSE(variants[0].keys.receiver_plane.has_value());
  EXPECT_EQ(variants[0].targets.size(), kEveryTarget.size() - 1);
  EXPECT_EQ(variants[1].keys.receiver_plane, true);
  EXPECT_EQ(variants[1].targets, kEveryTarget);
}

TEST(ManifestExpand, LoadedManifestNamesItsFile) {
  Result<Manifest> manifest = load_manifest(PENUMBRA_SOURCE_DIR "/permutations/default.json");
  ASSERT_TRUE(manifest.ok()) << manifest.error().to_string();
  EXPECT_EQ(manifest->source, PENUMBRA_SOURCE_DIR "/permutations/default.json");
  EXPECT_EQ(manifest->sets.at(1).json_path, "/sets/1");
}

}  // namespace
}  // namespace penumbra
