// Every variant of permutations/default.json passes the rules of every
// target, shared passes included, without a warning.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <tuple>
#include <utility>

#include "build/pass_plan.hpp"
#include "build/pipeline.hpp"
#include "penumbra/compiler/manifest.hpp"

namespace penumbra {
namespace {

TEST(DefaultVariants, PassEveryTargetsRules) {
  auto variants =
      load_variants(std::filesystem::path(PENUMBRA_SOURCE_DIR) / "permutations" / "default.json");
  ASSERT_TRUE(variants.ok()) << variants.error().to_string();
  ASSERT_EQ(variants->size(), 85u);
  const Pipeline pipeline(embedded_shaderlib(), std::nullopt);
  std::set<std::pair<Target, const PassStageSource*>> shared;
  // Each shared shader compiled once per target and the map encoding it is
  // built for (the depth pass and minmax_init decode the engine's map).
  std::set<std::tuple<Target, const PassStageSource*, MapEncoding>> compiled;
  for (const Variant& variant : *variants) {
    for (Target target : variant.targets) {
      for (const PassStageSource& source : pass_plan()) {
        if (!runs_pass(source.pass, variant)) continue;
        if (!source.per_variant) {
          shared.insert({target, &source});
          if (!compiled.insert({target, &source, job_encoding(source, variant)}).second) continue;
        }
        ShaderJob job = make_job(source, target, variant);
        const Status status = pipeline.run(job);
        ASSERT_TRUE(status.ok()) << status.error().to_string();
        EXPECT_TRUE(job.diagnostics.empty()) << job.describe();
      }
    }
  }
  // Every shared pass, the min-max build passes included, for every target.
  const auto shared_sources = std::ranges::count_if(
      pass_plan(), [](const PassStageSource& source) { return !source.per_variant; });
  EXPECT_EQ(shared.size(), kAllTargets.size() * static_cast<std::size_t>(shared_sources));
}

}  // namespace
}  // namespace penumbra
