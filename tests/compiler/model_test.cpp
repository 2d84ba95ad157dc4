// Names of techniques and targets, the targets' traits, and the variant
// naming rule.
#include "penumbra/model/model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "penumbra/compiler/targets.hpp"
#include "penumbra/model/shader_contract.hpp"

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
  EXPECT_EQ(parse_target("hlsl_dx11"), Target::hlsl_dx11);
  EXPECT_EQ(parse_target("hlsl_dx12"), std::nullopt);
}

// Direct3D 11 is Direct3D 10's dialect at shader model 5: its bytecode is
// vs_5_0/ps_5_0 in the DXBC container.
TEST(Model, Direct3D11BindsAsDirect3D10) {
  EXPECT_EQ(traits(Target::hlsl_dx11).dialect, ReflectionDialect::d3d10);
  EXPECT_EQ(traits(Target::hlsl_dx11).shader_model, 5);
  const auto format = bytecode_format(Target::hlsl_dx11, ShaderStage::fragment);
  ASSERT_TRUE(format.has_value());
  EXPECT_EQ(format->profile, "ps_5_0");
  EXPECT_EQ(format->vkd3d_type, "dxbc-tpf");
  EXPECT_EQ(format->extension, ".dxbc");
  EXPECT_FALSE(bytecode_format(Target::glsl450, ShaderStage::vertex).has_value());
}

TEST(Model, AllowedListsNameEveryValueInOrder) {
  EXPECT_EQ(allowed_techniques(),
            "hard, pcf_grid, pcf_poisson, pcss, minmax_pcf, backprojection, pcss_minmax, "
            "screen_blur, bitmask_backprojection");
  EXPECT_EQ(allowed_light_bits(), "16, 64, 256, 1024");
  EXPECT_EQ(allowed_targets(), "spirv, glsl450, glsl330, essl300, hlsl_dx11, hlsl_dx10, hlsl_dx9");
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
  EXPECT_EQ(variant_name(Technique::screen_blur, keys([](VariantKeys& k) { k.blur_radius = 4; })),
            "screen_blur_r4");
  EXPECT_EQ(variant_name(Technique::screen_blur, keys([](VariantKeys& k) {
                           k.blur_radius = 16;
                           k.depth_aware = true;
                         })),
            "screen_blur_r16_depth_aware");
  EXPECT_EQ(variant_name(Technique::bitmask_backprojection, keys([](VariantKeys& k) {
                           k.max_nodes = 4096;
                           k.light_bits = 256;
                         })),
            "bitmask_backprojection_n4096_bits256");
  EXPECT_EQ(variant_name(Technique::pcss, keys([](VariantKeys& k) {
                           k.blocker_samples = 16;
                           k.pcf_samples = 16;
                           k.disk = "poisson";
                           k.rotation = "ign";
                           k.receiver_plane = true;
                         })),
            "pcss_b16_p16_poisson_ign_receiver_plane");
  EXPECT_EQ(light_grid_side(1024), 32);
}

TEST(Model, FormNamesRoundTrip) {
  for (Form form : kAllForms) EXPECT_EQ(parse_form(to_string(form)), form);
  EXPECT_EQ(parse_form("shadow"), std::nullopt);
  EXPECT_EQ(allowed_forms(), "query, deferred, function");
}

// Every form brings the depth pass and the min-max chain; the query form
// its query, blur and composite passes, the deferred form its own pass.
TEST(Model, AVariantRunsThePassesOfItsForms) {
  Variant minmax;
  minmax.technique = Technique::minmax_pcf;
  minmax.forms = {Form::function};
  EXPECT_TRUE(builds_form(minmax, Form::function));
  EXPECT_TRUE(runs_pass(PassKind::depth, minmax));
  EXPECT_TRUE(runs_pass(PassKind::minmax_init, minmax));
  EXPECT_TRUE(runs_pass(PassKind::minmax_reduce, minmax));
  EXPECT_FALSE(runs_pass(PassKind::query, minmax));
  EXPECT_FALSE(runs_pass(PassKind::deferred, minmax));
  EXPECT_EQ(form_not_built(minmax, Form::query),
            "built without the query form (its forms: function)");
  EXPECT_EQ(form_not_built(minmax, Form::function), "");

  Variant blur;
  blur.technique = Technique::screen_blur;  // every form asked; it has the query form only
  EXPECT_EQ(built_forms(blur), std::vector<Form>{Form::query});
  EXPECT_TRUE(runs_pass(PassKind::composite, blur));
  EXPECT_FALSE(runs_pass(PassKind::deferred, blur));
  EXPECT_EQ(form_not_built(blur, Form::function), "technique screen_blur has no function form");
  blur.forms = {Form::function};
  EXPECT_FALSE(runs_pass(PassKind::blur_h, blur));

  Variant pcss;
  pcss.technique = Technique::pcss;
  pcss.forms = {Form::deferred};
  EXPECT_TRUE(runs_pass(PassKind::deferred, pcss));
  EXPECT_FALSE(runs_pass(PassKind::query, pcss));
  EXPECT_FALSE(runs_pass(PassKind::minmax_init, pcss));  // pcss reads no min-max mip
}

TEST(Model, GaussianWeightsAreNormalizedSymmetricAndPeaked) {
  for (int radius = 1; radius <= kMaxBlurRadius; ++radius) {
    const std::vector<float> w = gaussian_weights(radius);
    ASSERT_EQ(w.size(), static_cast<std::size_t>(2 * radius + 1)) << radius;
    double sum = 0.0;
    for (float x : w) sum += x;
    EXPECT_NEAR(sum, 1.0, 1e-6) << radius;
    for (int k = 1; k <= radius; ++k) {
      const auto at = [&](int tap) { return w[static_cast<std::size_t>(tap + radius)]; };
      EXPECT_EQ(at(k), at(-k)) << radius << " tap " << k;
      EXPECT_LT(at(k), at(k - 1)) << radius << " tap " << k;
      EXPECT_GT(at(k), 0.0f) << radius << " tap " << k;
    }
  }
}

TEST(Model, GaussianWeightsFollowSigmaHalfTheRadius) {
  // R = 2: sigma = 1, weights exp(-k^2 / 2) / sum for k = -2..2.
  const double e1 = std::exp(-0.5);
  const double e2 = std::exp(-2.0);
  const double sum = 1.0 + 2.0 * e1 + 2.0 * e2;
  EXPECT_EQ(gaussian_weights(2),
            (std::vector<float>{static_cast<float>(e2 / sum), static_cast<float>(e1 / sum),
                                static_cast<float>(1.0 / sum), static_cast<float>(e1 / sum),
                                static_cast<float>(e2 / sum)}));
}

}  // namespace
}  // namespace penumbra
