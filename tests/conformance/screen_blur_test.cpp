// screen_blur's chain on the device: the technique's pass list from the
// model (query, blur_h, blur_v, composite) run by Engine::run_passes with
// every target's own programs, as verify runs it: a constant factor
// stays constant after the blur, edges included (clamp-to-edge repeats the
// edge pixel); a step in the factor keeps its edge values and matches the
// CPU blur of the GPU's own factor (plain and depth-aware); the composite is
// the scene colour times the blurred factor. Every call runs under the
// validation layer.
#include "penumbra/reference/screen_blur.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "default_library.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/model/shadow_params.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/runtime/pass_driver.hpp"
#include "penumbra/verify/library_programs.hpp"
#include "screen_chain.hpp"

namespace penumbra::testing {
namespace {

constexpr int kWidth = 37;  // odd sizes: no power-of-two coincidences
constexpr int kHeight = 23;

// A map of kWidth x kHeight normalized depth: `left` where x < kWidth / 2, else `right`.
FloatImage split_map(float left, float right) {
  FloatImage map(kWidth, kHeight, 1);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) map.data[y * kWidth + x] = x < kWidth / 2 ? left : right;
  }
  return map;
}

// Receivers over the screen, one per map texel centre, at z `left` or `right`
// like split_map.
FloatImage split_receivers(float left, float right) {
  FloatImage receivers(kWidth, kHeight, 3);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      float* p = &receivers.data[3 * (y * kWidth + x)];
      p[0] = (static_cast<float>(x) + 0.5f) / static_cast<float>(kWidth);
      p[1] = (static_cast<float>(y) + 0.5f) / static_cast<float>(kHeight);
      p[2] = x < kWidth / 2 ? left : right;
    }
  }
  return receivers;
}

// Blocks of 5 x 4 texels alternating between 0 (shadow) and 1 (lit), so the
// factor varies along both axes.
FloatImage checker_map() {
  FloatImage map(kWidth, kHeight, 1);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) map.data[y * kWidth + x] = float((x / 5 + y / 4) % 2);
  }
  return map;
}

// Receivers like split_receivers, but at z `top` in rows y < kHeight / 2 and
// `bottom` below: a depth step across rows, for blur_v's depth test.
FloatImage row_split_receivers(float top, float bottom) {
  FloatImage receivers = split_receivers(top, top);
  for (int y = kHeight / 2; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) receivers.data[3 * (y * kWidth + x) + 2] = bottom;
  }
  return receivers;
}

double max_difference(const FloatImage& a, const FloatImage& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.data.size(); ++i) {
    worst = std::max(worst, std::abs(double(a.data[i]) - double(b.data[i])));
  }
  return worst;
}

class ScreenBlurChain : public ::testing::TestWithParam<std::string> {
 protected:
  // Runs the variant's chain for every target over `map` (normalized depth,
  // depth scale 1) and `receivers`; `check` gets each target's output.
  template <typename Check>
  void run_every_target(const FloatImage& map, const FloatImage& receivers, Check check) {
    auto built = build_default_variant(GetParam());
    ASSERT_TRUE(built) << built.error().to_string();
    const Library& library = (*built)->library();
    // Validation messages fail the test.
    auto engine = Engine::create({.device = "", .validation = true}, [](const Diagnostic& d) {
      if (d.where == "vulkan validation") ADD_FAILURE() << d.message;
    });
    ASSERT_TRUE(engine.ok()) << engine.error().to_string();
    const LibraryVariant* variant = library.find(GetParam());
    ASSERT_NE(variant, nullptr);
    const FloatImage colour = reference::scene_colour(kWidth, kHeight);
    const ParamBlock params = shadow_params(reference::builtin_scenes().front().light,
                                            {kWidth, kHeight, kWidth, kHeight}, 1.0f);
    const std::vector<PassKind> passes = runtime::select_passes(
        describe(variant->variant.technique).passes, /*draw_depth=*/false, /*deferred=*/false);
    for (Target target : variant->variant.targets) {
      SCOPED_TRACE(to_string(target));
      auto programs = load_passes(
          passes, [&](PassKind pass) { return load_executable(library, *variant, pass, target); });
      ASSERT_TRUE(programs.ok()) << programs.error().to_string();
      auto shadow_map = (*engine)->upload_shadow_map(map);
      ASSERT_TRUE(shadow_map.ok()) << shadow_map.error().to_string();
      auto outputs =
          (*engine)->run_passes(passes, program_map(*programs), **shadow_map,
                                {.receivers = &receivers, .scene_colour = &colour}, params);
      ASSERT_TRUE(outputs.ok()) << outputs.error().to_string();
      auto output = screen_chain(*outputs);
      ASSERT_TRUE(output.ok()) << output.error().to_string();
      ASSERT_EQ(output->blurred.width, kWidth);
      ASSERT_EQ(output->blurred.height, kHeight);
      ASSERT_EQ(output->composite.channels, 4);
      // The composite is the scene colour times the blurred factor, everywhere.
      EXPECT_LE(max_difference(output->composite, reference::composite(colour, output->blurred)),
                reference::kCompositeTolerance);
      // Nine point compares per pixel.
      for (float reads : output->texel_reads.data) ASSERT_EQ(reads, 9.0f);
      check(variant->variant, *output);
    }
  }
};

// Every receiver in front of a far map: factor 1 everywhere, and the blur,
// whose weights sum to 1, keeps it 1 up to the edges, where the taps past the
// edge read the edge pixel.
TEST_P(ScreenBlurChain, ConstantFactorStaysConstantUpToTheEdges) {
  run_every_target(split_map(1.0f, 1.0f), split_receivers(0.5f, 0.5f),
                   [](const Variant&, const ScreenChain& output) {
                     for (float f : output.factor.data) ASSERT_NEAR(f, 1.0f, 1e-6);
                     for (int y = 0; y < kHeight; ++y) {
                       for (int x = 0; x < kWidth; ++x) {
                         EXPECT_NEAR(output.blurred_h.at(x, y, 0), 1.0f, 1e-6) << x << ", " << y;
                         EXPECT_NEAR(output.blurred.at(x, y, 0), 1.0f, 1e-6) << x << ", " << y;
                       }
                     }
                   });
}

// Left half in shadow (map at 0), right half lit, receivers at two depths:
// the blur matches the CPU blur of the GPU's factor, horizontal pass and
// both; the edge columns, farther than R from the step, keep their values
// (clamp-to-edge, not wrap or a border colour).
TEST_P(ScreenBlurChain, StepMatchesTheCpuBlurOfTheGpuFactor) {
  run_every_target(
      split_map(0.0f, 1.0f), split_receivers(0.5f, 0.6f),
      [](const Variant& variant, const ScreenChain& output) {
        const FloatImage receivers = split_receivers(0.5f, 0.6f);
        const bool depth_aware = variant.keys.depth_aware.value_or(false);
        const FloatImage expected_h = reference::blur_horizontal(
            output.factor, variant.blur_weights, depth_aware ? &receivers : nullptr);
        EXPECT_LE(max_difference(output.blurred_h, expected_h), reference::kBlurTolerance);
        EXPECT_LE(max_difference(output.blurred,
                                 reference::screen_blur(variant, output.factor, receivers)),
                  reference::kBlurTolerance);
        for (int y = 0; y < kHeight; ++y) {
          EXPECT_EQ(output.blurred.at(0, y, 0), 0.0f) << y;
          EXPECT_NEAR(output.blurred.at(kWidth - 1, y, 0), 1.0f, 1e-6) << y;
        }
      });
}

// A factor that varies along both axes and receivers with a depth step
// across rows: blur_v's taps, its clamp at the top and bottom edges and the
// orientation of each pass against the next all show in the result.
TEST_P(ScreenBlurChain, CheckerMatchesTheCpuBlurOfTheGpuFactorAlongBothAxes) {
  run_every_target(
      checker_map(), row_split_receivers(0.5f, 0.6f),
      [](const Variant& variant, const ScreenChain& output) {
        const FloatImage receivers = row_split_receivers(0.5f, 0.6f);
        const bool depth_aware = variant.keys.depth_aware.value_or(false);
        // The factor really varies down a column (3x3 compares across blocks).
        EXPECT_NE(output.factor.at(2, 0, 0), output.factor.at(2, kHeight - 1, 0));
        const FloatImage expected_h = reference::blur_horizontal(
            output.factor, variant.blur_weights, depth_aware ? &receivers : nullptr);
        EXPECT_LE(max_difference(output.blurred_h, expected_h), reference::kBlurTolerance);
        EXPECT_LE(max_difference(output.blurred,
                                 reference::screen_blur(variant, output.factor, receivers)),
                  reference::kBlurTolerance);
      });
}

INSTANTIATE_TEST_SUITE_P(Default, ScreenBlurChain,
                         ::testing::Values("screen_blur_r4", "screen_blur_r4_depth_aware"),
                         [](const auto& param_info) { return test_name(param_info.param); });

}  // namespace
}  // namespace penumbra::testing
