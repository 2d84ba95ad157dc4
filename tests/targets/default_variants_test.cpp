// Every variant of permutations/default.json passes the rules of every
// target, shared passes included; prints each variant's ps_3_0 estimate
// (the calibration table in docs/targets.md).
#include <gtest/gtest.h>

#include <iostream>
#include <map>

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
  ASSERT_EQ(variants->size(), 22u);
  const Pipeline pipeline(std::nullopt);
  std::map<std::string, int> estimates;
  for (const Variant& variant : *variants) {
    for (Target target : variant.targets) {
      for (const PassStageSource& source : pass_plan()) {
        if (!source.per_variant && &variant != &variants->front()) continue;  // once per target
        ShaderJob job = make_job(source, target, &variant);
        const Status status = pipeline.run(job);
        ASSERT_TRUE(status.ok()) << status.error().to_string();
        const bool estimated = target == Target::hlsl_dx9 && job.stage == ShaderStage::fragment;
        EXPECT_EQ(job.estimated_slots > 0, estimated) << job.describe();
        EXPECT_EQ(job.diagnostics.size(), job.estimated_slots > kPs30MinimumSlots ? 1u : 0u)
            << job.describe();
        if (estimated && source.per_variant) estimates[variant.name] = job.estimated_slots;
      }
    }
  }
  std::cout << "estimated ps_3_0 slots of hlsl_dx9 query.frag (over " << kPs30MinimumSlots
            << " warns):\n";
  for (const auto& [name, slots] : estimates) std::cout << "  " << name << " " << slots << "\n";
  EXPECT_LT(estimates.at("hard"), kPs30MinimumSlots);
  // More taps, more slots.
  EXPECT_LT(estimates.at("pcf_poisson_p16_poisson"), estimates.at("pcf_poisson_p25_poisson"));
  EXPECT_LT(estimates.at("pcf_poisson_p32_poisson"), estimates.at("pcf_poisson_p64_poisson"));
  EXPECT_LT(estimates.at("pcss_b16_p16_poisson"), estimates.at("pcss_b32_p16_poisson"));
  EXPECT_LT(estimates.at("pcss_b32_p32_poisson"), estimates.at("pcss_b32_p64_poisson"));
}

}  // namespace
}  // namespace penumbra
