// The deferred pass run as an engine runs it (check_deferred_mask): the
// camera's depth of the report's stage, in each target's conventions, read
// by the pass, which rebuilds each receiver with the camera's inverse and
// the light's view-projection; against the CPU reference on those receivers,
// and the camera against the ray cast.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "default_library.hpp"
#include "penumbra/verify/function_form.hpp"
#include "validation_messages.hpp"

namespace penumbra::testing {
namespace {

// One variant per technique and encoding, and the keys that change what the
// pass derives: rotation (the pixel) and receiver_plane (screen derivatives
// of rebuilt receivers).
const std::vector<std::string> kVariants = {
    "hard",
    "pcf_grid_k3_perspective",
    "pcf_poisson_p16_poisson_receiver_plane",
    "pcss_b16_p16_poisson_perspective_reversed",
    "pcss_b16_p16_poisson_ign",
    "minmax_pcf_k8_perspective_reversed",
    "pcss_minmax_p16_poisson_orthographic",
    "backprojection_perspective_reversed",
    "bitmask_backprojection_bits64_perspective_reversed",
    "pcss_b16_p16_poisson_receiver_plane_perspective_reversed_atlas",
    "pcss_b16_p16_poisson_receiver_plane_perspective_reversed_array"};

Result<std::unique_ptr<Engine>> validated_engine() {
  return Engine::create({.device = "", .validation = true}, fail_on_validation_messages());
}

class DeferredExecution : public ::testing::TestWithParam<std::string> {};

TEST_P(DeferredExecution, EveryTargetMatchesTheReferenceOnTheCamerasStage) {
  auto built = build_default_variant(GetParam());
  ASSERT_TRUE(built) << built.error().to_string();
  auto engine = validated_engine();
  ASSERT_TRUE(engine) << engine.error().to_string();
  const Library& library = (*built)->library();
  const LibraryVariant& entry = library.variants.at(0);
  for (Target target : entry.variant.targets) {
    SCOPED_TRACE(std::string(to_string(target)));
    auto check = check_deferred_mask(**engine, library, entry, target);
    ASSERT_TRUE(check.ok()) << check.error().to_string();
    const reference::Comparison& c = check->comparison;
    EXPECT_TRUE(check->pass) << check->execution.front_end << ": max error " << c.max_abs_error
                             << " (tolerance " << c.tolerance << "), " << c.over_tolerance
                             << " pixels over, " << c.ambiguous << " of " << c.pixels
                             << " ambiguous; camera agreement " << check->camera_agreement;
    EXPECT_GT(check->surface_pixels, std::size_t(320 * 240 / 4));
    EXPECT_GT(c.compared, c.pixels * 49 / 50);
  }
}

INSTANTIATE_TEST_SUITE_P(Default, DeferredExecution, ::testing::ValuesIn(kVariants),
                         [](const auto& param_info) { return test_name(param_info.param); });

// A pass that rebuilds the camera's rows upside down is caught: the check
// is not satisfied by any picture.
TEST(DeferredExecutionCheck, FailsWhenThePassFlipsTheCamerasRows) {
  auto built = build_default_variant("pcss_b16_p16_poisson_perspective_reversed");
  ASSERT_TRUE(built) << built.error().to_string();
  const std::filesystem::path copy =
      std::filesystem::path(::testing::TempDir()) / "penumbra_deferred_flipped";
  std::filesystem::remove_all(copy);
  std::filesystem::copy((*built)->library().root, copy, std::filesystem::copy_options::recursive);
  auto original = load_library(copy);
  ASSERT_TRUE(original) << original.error().to_string();
  const PassFiles& files =
      original->variants.at(0).passes.at(PassKind::deferred).at(Target::glsl450);
  const std::filesystem::path frag = copy / files.frag;
  std::stringstream text;
  text << std::ifstream(frag).rdbuf();
  std::string source = text.str();
  const std::string rows = "(screen_uv.y - 0.5) / 0.5";
  const std::size_t at = source.find(rows);
  ASSERT_NE(at, std::string::npos) << frag;
  source.replace(at, rows.size(), "(0.5 - screen_uv.y) / 0.5");
  std::ofstream(frag) << source;

  auto library = load_library(copy);
  ASSERT_TRUE(library) << library.error().to_string();
  auto engine = validated_engine();
  ASSERT_TRUE(engine) << engine.error().to_string();
  auto check = check_deferred_mask(**engine, *library, library->variants.at(0), Target::glsl450);
  ASSERT_TRUE(check.ok()) << check.error().to_string();
  EXPECT_FALSE(check->pass);
  EXPECT_GT(check->comparison.over_tolerance, 1000u);
  std::filesystem::remove_all(copy);
}

}  // namespace
}  // namespace penumbra::testing
