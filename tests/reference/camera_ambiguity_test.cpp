// The share of a camera's view the reference marks ambiguous
// (docs/verification.md, "Ambiguity in a camera view"): the report's stage
// seen from its camera, at half, one and twice its light's size, for every
// default variant on the library's own map. verify's 2% limit is for its
// light-view scenes; a camera view sees depth edges at every distance, and
// pcss's blocker search and receiver_plane's depth slopes mark more there.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "default_library.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/reference/stage.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {
namespace {

// The limits docs/verification.md states for a camera view, as shares of
// the pixels that see a surface: pcss and receiver_plane variants, and the
// rest.
constexpr double kBlockerSearchLimit = 0.05;
constexpr double kOtherLimit = 0.01;

double camera_view_limit(const Variant& variant) {
  const bool marks_more =
      variant.technique == Technique::pcss || variant.keys.receiver_plane.value_or(false);
  return marks_more ? kBlockerSearchLimit : kOtherLimit;
}

struct ViewShares {
  double of_surface = 0.0;   // ambiguous / pixels that see a surface
  double of_penumbra = 0.0;  // ambiguous / surface pixels the reference puts in penumbra
};

// `variant` on the report's stage, its light's half-width times `scale`.
ViewShares camera_shares(const Variant& variant, double scale) {
  Stage stage = report_stage();
  stage.scene.light.light_world_size *= scale;
  const Scene& scene = stage.scene;
  const StageView seen = view(stage, scene.receivers_width, scene.receivers_height);
  const FloatImage map = ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z);
  auto image = evaluate_image(variant, map, scene.light, seen.receivers, SamplingPrecision{},
                              shader_limits(Target::spirv));
  EXPECT_TRUE(image.ok()) << image.error().to_string();
  if (!image.ok()) return {};
  std::size_t surface = 0, penumbra = 0, ambiguous = 0;
  for (std::size_t p = 0; p < seen.surfaces.size(); ++p) {
    if (seen.surfaces[p] == Surface::none) continue;
    ++surface;
    const float v = image->visibility.data[p];
    penumbra += v > 0.0f && v < 1.0f;
    ambiguous += image->ambiguous.data[p] != 0.0f;
  }
  return {double(ambiguous) / double(surface),
          penumbra ? double(ambiguous) / double(penumbra) : 0.0};
}

class CameraAmbiguity : public ::testing::TestWithParam<std::string> {};

TEST_P(CameraAmbiguity, StaysWithinTheCameraViewLimits) {
  const Variant& variant = *testing::find_default_variant(GetParam());
  for (const double scale : {0.5, 1.0, 2.0}) {
    const ViewShares shares = camera_shares(variant, scale);
    std::printf("%s, light x%g: %.2f%% of the surface pixels, %.2f%% of those in penumbra\n",
                variant.name.c_str(), scale, 100.0 * shares.of_surface, 100.0 * shares.of_penumbra);
    EXPECT_LE(shares.of_surface, camera_view_limit(variant)) << "light x" << scale;
  }
}

// The default variants on the library's own map, but screen_blur, whose
// factor is a screen's, not a view's of a stage.
std::vector<std::string> camera_variants() {
  std::vector<std::string> names;
  for (const Variant& v : testing::default_variants()) {
    if (v.technique == Technique::screen_blur) continue;
    if (map_encoding(v.keys) != MapEncoding::linear) continue;
    names.push_back(v.name);
  }
  return names;
}

INSTANTIATE_TEST_SUITE_P(DefaultVariants, CameraAmbiguity, ::testing::ValuesIn(camera_variants()),
                         [](const auto& param_info) {
                           return testing::test_name(param_info.param);
                         });

}  // namespace
}  // namespace penumbra::reference
