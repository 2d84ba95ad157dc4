// The function form run as an engine runs it (check_function_form): the
// report's stage drawn from its camera by engine-like shaders of each text
// target, compiled by that target's front end, calling penumbra_visibility()
// on the map the target's depth pass drew; against the CPU reference on the
// receivers the GPU called it with, and the camera against the ray cast.
#include <gtest/gtest.h>

#include "default_library.hpp"
#include "penumbra/model/target_traits.hpp"
#include "penumbra/verify/function_form.hpp"
#include "validation_messages.hpp"

namespace penumbra::testing {
namespace {

// One variant per technique and encoding, and the keys that change what
// the function takes or derives: rotation (the pixel) and receiver_plane
// (screen derivatives). The min-max techniques read the mip the target's
// build passes made of the map. An atlas or array variant takes its light
// at each call.
const std::vector<std::string> kVariants = {
    "hard",
    "pcf_grid_k3",
    "pcf_grid_k3_perspective",
    "pcf_poisson_p16_poisson_receiver_plane",
    "pcss_b16_p16_poisson_perspective_reversed",
    "pcss_b16_p16_poisson_ign",
    "minmax_pcf_k8_orthographic",
    "pcss_minmax_p32_poisson_ign",
    "backprojection_perspective",
    "bitmask_backprojection_bits64_orthographic",
    "pcf_poisson_p16_poisson_ign_atlas",
    "pcss_b16_p16_poisson_receiver_plane_orthographic_atlas",
    "pcf_grid_k3_array",
    "pcss_b16_p16_poisson_receiver_plane_perspective_reversed_array"};

class FunctionFormExecution : public ::testing::TestWithParam<std::string> {};

TEST_P(FunctionFormExecution, EveryTextTargetMatchesTheReferenceOnTheCamerasStage) {
  auto built = build_default_variant(GetParam());
  ASSERT_TRUE(built) << built.error().to_string();
  auto engine = Engine::create({.device = "", .validation = true}, fail_on_validation_messages());
  ASSERT_TRUE(engine) << engine.error().to_string();
  const Library& library = (*built)->library();
  // Each text target the variant is built for (bitmask_backprojection:
  // not hlsl_dx9).
  for (Target target : library.variants.at(0).variant.targets) {
    if (!traits(target).is_text) continue;
    SCOPED_TRACE(std::string(to_string(target)));
    auto check = check_function_form(**engine, library, library.variants.at(0), target);
    ASSERT_TRUE(check.ok()) << check.error().to_string();
    const reference::Comparison& c = check->comparison;
    EXPECT_TRUE(check->pass) << check->execution.front_end << ": max error " << c.max_abs_error
                             << " (tolerance " << c.tolerance << "), " << c.over_tolerance
                             << " pixels over, " << c.ambiguous << " of " << c.pixels
                             << " ambiguous; camera agreement " << check->camera_agreement;
    // The stage covers over a quarter of the picture; nearly all of it is
    // compared.
    EXPECT_GT(check->surface_pixels, std::size_t(320 * 240 / 4));
    EXPECT_EQ(c.pixels, check->surface_pixels);
    EXPECT_GT(c.compared, c.pixels * 49 / 50);
  }
}

INSTANTIATE_TEST_SUITE_P(Default, FunctionFormExecution, ::testing::ValuesIn(kVariants),
                         [](const auto& param_info) { return test_name(param_info.param); });

}  // namespace
}  // namespace penumbra::testing
