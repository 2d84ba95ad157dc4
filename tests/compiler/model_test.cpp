// Names of techniques and targets, and the variant naming rule.
#include "penumbra/compiler/model.hpp"

#include <gtest/gtest.h>

namespace penumbra {
namespace {

TEST(Model, TechniqueNamesRoundTrip) {
  for (Technique technique : kAllTechniques) {
    EXPECT_EQ(parse_technique(to_string(technique)), technique);
  }
  EXPECT_EQ(to_string(Technique::pcf_poisson), "pcf_poisson");
  EXPECT_EQ(parse_technique("pcss"), Technique::pcss);
  EXPECT_EQ(parse_technique("PCSS"), std::nullopt);
  EXPECT_EQ(parse_technique(""), std::nullopt);
}

TEST(Model, TargetNamesRoundTrip) {
  for (Target target : kAllTargets) EXPECT_EQ(parse_target(to_string(target)), target);
  EXPECT_EQ(to_string(Target::hlsl_dx9), "hlsl_dx9");
  EXPECT_EQ(parse_target("essl300"), Target::essl300);
  EXPECT_EQ(parse_target("hlsl_dx11"), std::nullopt);
}

TEST(Model, AllowedListsNameEveryValueInOrder) {
  EXPECT_EQ(allowed_techniques(),
            "hard, pcf_grid, pcf_poisson, pcss, minmax_pcf, backprojection, pcss_minmax");
  EXPECT_EQ(allowed_targets(), "spirv, glsl450, glsl330, essl300, hlsl_dx10, hlsl_dx9");
}

TEST(Model, VariantNames) {
  const auto keys = [](auto set) {
    VariantKeys k;
    set(k);
    return k;
  };
  EXPECT_EQ(variant_name(Technique::hard, {}), "hard");
  EXPECT_EQ(variant_name(Technique::pcf_grid, keys([](VariantKeys& k) { k.kernel = 5; })),
            "pcf_grid_k5");
  EXPECT_EQ(variant_name(Technique::pcf_poisson, keys([](VariantKeys& k) {
                           k.pcf_samples = 16;
                           k.disk = "poisson";
                         })),
            "pcf_poisson_p16_poisson");
  EXPECT_EQ(variant_name(Technique::pcss, keys([](VariantKeys& k) {
                           k.blocker_samples = 16;
                           k.pcf_samples = 25;
                           k.disk = "whitepaper16";
                         })),
            "pcss_b16_p25_whitepaper16");
  EXPECT_EQ(variant_name(Technique::minmax_pcf, keys([](VariantKeys& k) {
                           k.kernel = 24;
                           k.traversal = "brute_force";
                         })),
            "minmax_pcf_k24_brute_force");
  EXPECT_EQ(
      variant_name(Technique::backprojection, keys([](VariantKeys& k) { k.max_nodes = 4096; })),
      "backprojection_n4096");
}

}  // namespace
}  // namespace penumbra
