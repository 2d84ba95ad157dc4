// Every variant of permutations/default.json passes the rules of every
// target, shared passes included; prints each variant's ps_3_0 estimate
// (the calibration table in docs/targets.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <set>
#include <utility>

#include "build/pass_plan.hpp"
#include "build/pipeline.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "targets/slot_estimate.hpp"

namespace penumbra {
namespace {

TEST(DefaultVariants, PassEveryTargetsRules) {
  auto variants =
      load_variants(std::filesystem::path(PENUMBRA_SOURCE_DIR) / "permutations" / "default.json");
  ASSERT_TRUE(variants.ok()) << variants.error().to_string();
  ASSERT_EQ(variants->size(), 33u);
  const Pipeline pipeline(std::nullopt);
  std::map<std::string, int> estimates;
  std::set<std::pair<Target, const PassStageSource*>> shared;  // each compiled once per target
  for (const Variant& variant : *variants) {
    for (Target target : variant.targets) {
      for (const PassStageSource& source : pass_plan()) {
        if (!runs_pass(source.pass, variant)) continue;
        if (!source.per_variant && !shared.insert({target, &source}).second) continue;
        ShaderJob job = make_job(source, target, &variant);
        const Status status = pipeline.run(job);
        ASSERT_TRUE(status.ok()) << status.error().to_string();
        const bool estimated = target == Target::hlsl_dx9 && job.stage == ShaderStage::fragment;
        EXPECT_EQ(job.estimated_slots > 0, estimated) << job.describe();
        EXPECT_EQ(job.diagnostics.size(), job.estimated_slots > kPs30MinimumSlots ? 1u : 0u)
            << job.describe();
        if (estimated) {
          const std::string shared_name = std::string(source.file_stem) + " (shared)";
          // A variant's query pass goes by the variant's name, its other
          // passes (screen_blur's blur_h, blur_v) by "name.pass".
          const std::string own_name = source.pass == PassKind::query
                                           ? variant.name
                                           : variant.name + "." + std::string(source.file_stem);
          estimates[source.per_variant ? own_name : shared_name] = job.estimated_slots;
        }
      }
    }
  }
  // Every shared pass, the min-max build passes included, for every target.
  const auto shared_sources = std::ranges::count_if(
      pass_plan(), [](const PassStageSource& source) { return !source.per_variant; });
  EXPECT_EQ(shared.size(), kAllTargets.size() * static_cast<std::size_t>(shared_sources));
  std::cout << "estimated ps_3_0 slots of hlsl_dx9 fragment shaders (over " << kPs30MinimumSlots
            << " warns):\n";
  for (const auto& [name, slots] : estimates) std::cout << "  " << name << " " << slots << "\n";
  EXPECT_LT(estimates.at("hard"), kPs30MinimumSlots);
  // More taps, more slots.
  EXPECT_LT(estimates.at("pcf_poisson_p16_poisson"), estimates.at("pcf_poisson_p25_poisson"));
  EXPECT_LT(estimates.at("pcf_poisson_p32_poisson"), estimates.at("pcf_poisson_p64_poisson"));
  EXPECT_LT(estimates.at("pcss_b16_p16_poisson"), estimates.at("pcss_b32_p16_poisson"));
  EXPECT_LT(estimates.at("pcss_b32_p32_poisson"), estimates.at("pcss_b32_p64_poisson"));
  // The min-max walks stay rolled loops: the kernel does not change the code,
  // and their estimated slots, like the build passes', are within the 512
  // every ps_3_0 device holds. (The instructions a walk executes depend on
  // the data and are not checked: docs/targets.md.)
  EXPECT_EQ(estimates.at("minmax_pcf_k8"), estimates.at("minmax_pcf_k64"));
  EXPECT_LT(estimates.at("minmax_pcf_k64"), kPs30MinimumSlots);
  EXPECT_LT(estimates.at("backprojection"), kPs30MinimumSlots);
  EXPECT_LT(estimates.at("minmax_init (shared)"), kPs30MinimumSlots);
  EXPECT_LT(estimates.at("minmax_reduce (shared)"), kPs30MinimumSlots);
  // pcss_minmax's search is at most four node reads, cheaper than 16 disk taps.
  EXPECT_LT(estimates.at("pcss_minmax_p16_poisson"), estimates.at("pcss_b16_p16_poisson"));
  // screen_blur: nine point compares, then 2R + 1 taps per blur pass (unrolled,
  // so a wider blur costs more), two reads per tap when depth-aware.
  EXPECT_LT(estimates.at("screen_blur_r2"), kPs30MinimumSlots);
  EXPECT_LT(estimates.at("screen_blur_r2.blur_h"), estimates.at("screen_blur_r8.blur_h"));
  EXPECT_LT(estimates.at("screen_blur_r4.blur_v"),
            estimates.at("screen_blur_r4_depth_aware.blur_v"));
  EXPECT_LT(estimates.at("screen_blur_r8.blur_v"), kPs30MinimumSlots);
  EXPECT_LT(estimates.at("composite (shared)"), kPs30MinimumSlots);
}

}  // namespace
}  // namespace penumbra
