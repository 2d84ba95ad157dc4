// verify's plan (verify/src/verify_plan.cpp), computed without a device: the
// pairs each shard runs, the variants that prepare each target's maps and
// min-max mips, the paths, the progress total, and bad input refused.
#include "verify_plan.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>

#include "library_entries.hpp"

namespace penumbra::testing {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

VerifyPlan plan(const Library& lib, const VerifyOptions& options = {}) {
  auto planned = plan_verify(lib, options);
  EXPECT_TRUE(planned) << (planned ? "" : planned.error().to_string());
  return planned ? *planned : VerifyPlan{};
}

// Every (variant, target) of a plan, as "name [target]".
std::vector<std::string> pairs(const Library& lib, const VerifyPlan& p) {
  std::vector<std::string> out;
  for (const PlannedVariant& v : p.variants) {
    for (const PlannedPair& pair : v.pairs) {
      out.push_back(lib.variants[v.index].variant.name + " [" +
                    std::string(to_string(pair.target)) + "]");
    }
  }
  return out;
}

TEST(VerifyPlan, RunsEveryPairInLibraryOrderOnEveryPath) {
  const Library lib = planned_library();
  const VerifyPlan p = plan(lib);
  EXPECT_THAT(pairs(lib, p),
              ElementsAre("hard [spirv]", "hard [glsl450]", "pcss_perspective [spirv]",
                          "minmax_pcf [spirv]", "minmax_pcf [glsl450]", "minmax_dx9 [hlsl_dx9]"));
  EXPECT_EQ(p.pair_count(), 6u);
  EXPECT_THAT(p.paths, ElementsAre("vulkan", "bytecode", "gl", "d3d9", "d3d10", "d3d11"));
  for (const PlannedVariant& v : p.variants) EXPECT_FALSE(v.other_shards);
}

TEST(VerifyPlan, PreparesEachTargetsMapsWithItsFirstVariantPerEncoding) {
  const Library lib = planned_library();
  const VerifyPlan p = plan(lib);
  const MapKey spirv_linear{Target::spirv, MapEncoding::linear};
  const MapKey spirv_perspective{Target::spirv, MapEncoding::perspective};
  EXPECT_EQ(p.depth_preparers.at(spirv_linear), 0u);       // hard
  EXPECT_EQ(p.depth_preparers.at(spirv_perspective), 1u);  // pcss_perspective
  EXPECT_EQ(p.depth_preparers.at({Target::hlsl_dx9, MapEncoding::linear}), 3u);
  // The mip's: the first variant that reads one, not hard.
  EXPECT_EQ(p.minmax_preparers.at(spirv_linear), 2u);
  EXPECT_FALSE(p.minmax_preparers.contains(spirv_perspective));
  const PlannedPair& hard = p.variants[0].pairs[0];
  EXPECT_EQ(hard.maps, spirv_linear);
  EXPECT_FALSE(hard.minmax_preparer);
  const PlannedPair& minmax = p.variants[2].pairs[0];
  EXPECT_EQ(minmax.depth_preparer, 0u);
  EXPECT_EQ(minmax.minmax_preparer, 2u);
}

TEST(VerifyPlan, OptionsNarrowThePairsThePreparersAndThePaths) {
  const Library lib = planned_library();
  VerifyOptions options;
  options.variants = {"minmax_pcf"};
  options.targets = {Target::glsl450};
  options.paths = {"gl", "vulkan"};
  const VerifyPlan p = plan(lib, options);
  EXPECT_THAT(pairs(lib, p), ElementsAre("minmax_pcf [glsl450]"));
  EXPECT_EQ(p.pair_count(), 1u);
  // Prepared with the variant that is run, not the library's first.
  EXPECT_EQ(p.variants[0].pairs[0].depth_preparer, 2u);
  EXPECT_THAT(p.paths, ElementsAre("vulkan", "gl"));  // report order
  EXPECT_TRUE(p.runs_path("gl"));
  EXPECT_FALSE(p.runs_path("d3d9"));
}

TEST(VerifyPlan, ShardsSplitThePairsAndAgreeOnThePreparers) {
  const Library lib = planned_library();
  const VerifyPlan whole = plan(lib);
  const std::vector<std::string> all = pairs(lib, whole);
  std::multiset<std::string> union_of_shards;
  std::map<MapKey, int> depth_reporters;
  std::map<MapKey, int> minmax_reporters;
  std::size_t total = 0;
  for (int index = 1; index <= 3; ++index) {
    VerifyOptions options;
    options.shard = {index, 3};
    const VerifyPlan p = plan(lib, options);
    EXPECT_EQ(p.variants.size(), whole.variants.size()) << "every shard lists every variant";
    EXPECT_EQ(p.depth_preparers, whole.depth_preparers);
    EXPECT_EQ(p.minmax_preparers, whole.minmax_preparers);
    for (const std::string& pair : pairs(lib, p)) union_of_shards.insert(pair);
    total += p.pair_count();
    for (const auto& [key, _] : p.depth_preparers) depth_reporters[key] += p.reports_depth(key);
    for (const auto& [key, _] : p.minmax_preparers) minmax_reporters[key] += p.reports_minmax(key);
    for (const PlannedVariant& v : p.variants) {
      EXPECT_EQ(v.other_shards, v.pairs.size() < lib.variants[v.index].variant.targets.size());
    }
  }
  EXPECT_EQ(union_of_shards, std::multiset<std::string>(all.begin(), all.end()));
  EXPECT_EQ(total, whole.pair_count());
  // Each map's checks are reported by exactly one shard.
  for (const auto& [key, count] : depth_reporters) EXPECT_EQ(count, 1) << to_string(key.first);
  for (const auto& [key, count] : minmax_reporters) EXPECT_EQ(count, 1) << to_string(key.first);
}

TEST(VerifyPlan, RefusesBadInputNamingIt) {
  const auto refused = [](const Library& lib, const VerifyOptions& options) {
    auto p = plan_verify(lib, options);
    EXPECT_FALSE(p);
    if (p) return std::string();
    EXPECT_EQ(p.error().kind, Error::Kind::bad_input);
    return p.error().to_string();
  };
  const Library lib = planned_library();
  Library empty;
  empty.root = "empty";
  EXPECT_THAT(refused(empty, {}), HasSubstr("empty: the library has no variants"));
  VerifyOptions options;
  options.variants = {"pcss_nonesuch"};
  EXPECT_THAT(refused(lib, options), HasSubstr("pcss_nonesuch: no such variant in lib"));
  options = {};
  options.paths = {"d3d12"};
  EXPECT_THAT(refused(lib, options),
              HasSubstr("path d3d12: no such execution path; allowed: vulkan, bytecode, gl"));
  options = {};
  options.skipped = {"metal"};
  EXPECT_THAT(refused(lib, options), HasSubstr("skipped path metal"));
  options = {};
  options.shard = {3, 2};
  EXPECT_THAT(refused(lib, options), HasSubstr("shard 3/2: I must be in 1..N"));
  options.shard = {1, 0};
  EXPECT_THAT(refused(lib, options), HasSubstr("I must be in 1..N"));
}

}  // namespace
}  // namespace penumbra::testing
