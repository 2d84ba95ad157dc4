// `penumbra eval` and `penumbra verify` on screen_blur: eval writes the
// blurred factor from the device's chain, and --reference the CPU chain's,
// which agree away from the pixels a point-sample ambiguity can reach
// through the blur; --texel-reads gives the factor pass's nine reads; verify
// records the factor, blur and composite checks per scene and leaves the GL
// run unexecuted with its reason.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_harness.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/reference/screen_blur.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/support/pfm.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

constexpr const char* kManifest = R"({
  "schema": 1,
  "targets": ["spirv", "glsl450"],
  "sets": [{"technique": "screen_blur", "blur_radius": [2]},
           {"technique": "screen_blur", "blur_radius": [4], "depth_aware": true}]})";

class ScreenBlurCommand : public EvalFixture {
 protected:
  static void SetUpTestSuite() { set_up_eval("screen-blur", kManifest); }
  static void TearDownTestSuite() { tear_down_eval(); }

  // eval's output for `variant` with `extra` arguments, or an empty image (with a failure).
  static FloatImage eval(const std::string& variant, const std::string& file,
                         const std::string& extra) {
    const CliRun run = run_penumbra(eval_args(variant, "-o " + path(file) + " " + extra));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    auto image = read_pfm(dir_->path() / file);
    EXPECT_TRUE(image.ok());
    return image.ok() ? *image : FloatImage();
  }
};

// The device's blurred factor and the CPU chain's agree wherever no
// ambiguous factor pixel lies within the blur's R-pixel square.
void expect_device_matches_reference(const std::string& name, const FloatImage& device,
                                     const FloatImage& cpu, const FloatImage& map,
                                     const FloatImage& receivers, const Library& library) {
  const Variant& variant = library.find(name)->variant;
  ASSERT_EQ(device.width, receivers.width);
  ASSERT_EQ(device.height, receivers.height);
  ASSERT_EQ(device.channels, 1);
  ASSERT_EQ(cpu.width, receivers.width);
  auto factor = reference::evaluate_image(variant, map, LightParams{}, receivers,
                                          reference::SamplingPrecision{});
  ASSERT_TRUE(factor.ok()) << factor.error().to_string();
  const int radius = *variant.keys.blur_radius;
  std::size_t compared = 0;
  for (int j = 0; j < device.height; ++j) {
    for (int i = 0; i < device.width; ++i) {
      bool near_ambiguous = false;
      for (int dj = -radius; dj <= radius && !near_ambiguous; ++dj) {
        for (int di = -radius; di <= radius; ++di) {
          const int x = std::clamp(i + di, 0, device.width - 1);
          const int y = std::clamp(j + dj, 0, device.height - 1);
          if (factor->ambiguous.at(x, y) != 0.0f) near_ambiguous = true;
        }
      }
      if (near_ambiguous) continue;
      // The factor's tolerance, then the blur's.
      ASSERT_NEAR(device.at(i, j), cpu.at(i, j),
                  reference::tolerance(Technique::screen_blur, reference::SamplingPrecision{}) +
                      reference::kBlurTolerance)
          << name << " pixel " << i << ", " << j;
      ++compared;
    }
  }
  EXPECT_GT(compared, device.pixel_count() / 2) << name;
}

TEST_F(ScreenBlurCommand, DeviceChainAgreesWithTheReferenceChain) {
  auto library = load_library(lib());
  ASSERT_TRUE(library.ok()) << library.error().to_string();
  for (const std::string name : {"screen_blur_r2", "screen_blur_r4_depth_aware"}) {
    const FloatImage device = eval(name, name + "_device.pfm", "");
    const FloatImage cpu = eval(name, name + "_cpu.pfm", "--reference");
    expect_device_matches_reference(name, device, cpu, map_, receivers_, *library);
    // The blur changes the factor: the outputs are not the unblurred factor.
    auto factor = reference::evaluate_image(library->find(name)->variant, map_, LightParams{},
                                            receivers_, reference::SamplingPrecision{});
    ASSERT_TRUE(factor.ok());
    double changed = 0.0;
    for (std::size_t p = 0; p < cpu.pixel_count(); ++p) {
      changed = std::max(changed, std::abs(double(cpu.data[p]) - factor->visibility.data[p]));
    }
    EXPECT_GT(changed, 0.01) << name;
  }
}

TEST_F(ScreenBlurCommand, TexelReadsAreTheFactorPassesNineReads) {
  const CliRun run = run_penumbra(eval_args(
      "screen_blur_r2", "-o " + path("reads_vis.pfm") + " --texel-reads " + path("reads.pfm")));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto reads = read_pfm(dir_->path() / "reads.pfm");
  ASSERT_TRUE(reads.ok());
  ASSERT_EQ(reads->pixel_count(), receivers_.pixel_count());
  for (float r : reads->data) ASSERT_EQ(r, 9.0f);
}

TEST_F(ScreenBlurCommand, VerifyRecordsTheThreeChecksPerScene) {
  const CliRun run = run_penumbra("verify '" + lib().string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_THAT(run.out, HasSubstr("PASS screen_blur_r2 [spirv] max error"));
  EXPECT_THAT(run.out, HasSubstr(", blur "));
  std::ifstream in(lib() / "verify.json");
  const nlohmann::json report = nlohmann::json::parse(in);
  std::filesystem::remove(lib() / "verify.json");
  EXPECT_TRUE(report.at("pass").get<bool>());
  const std::size_t scenes = reference::builtin_scenes().size();
  ASSERT_EQ(report.at("variants").size(), 2u);
  for (const auto& variant : report.at("variants")) {
    int vulkan_runs = 0;
    for (const auto& target_run : variant.at("runs")) {
      // The chain runs on OpenGL too; a GL run is skipped only where there is no GL.
      if (!target_run.at("executed").get<bool>()) {
        EXPECT_EQ(target_run.at("backend"), "gl") << target_run.dump();
        continue;
      }
      if (target_run.at("backend") == "vulkan") ++vulkan_runs;
      ASSERT_EQ(target_run.at("scenes").size(), scenes);
      for (const auto& scene : target_run.at("scenes")) {
        EXPECT_TRUE(scene.at("pass").get<bool>()) << scene.dump();
        EXPECT_TRUE(scene.at("factor").at("pass").get<bool>()) << scene.dump();
        EXPECT_EQ(scene.at("blur").at("tolerance").get<double>(), reference::kBlurTolerance);
        EXPECT_TRUE(scene.at("blur").at("pass").get<bool>()) << scene.dump();
        EXPECT_EQ(scene.at("composite").at("tolerance").get<double>(),
                  reference::kCompositeTolerance);
        EXPECT_TRUE(scene.at("composite").at("pass").get<bool>()) << scene.dump();
        EXPECT_EQ(scene.at("composite").at("values").get<std::size_t>(),
                  4 * scene.at("blur").at("values").get<std::size_t>());
        EXPECT_EQ(scene.at("mean_texel_reads").get<double>(), 9.0);
      }
    }
    EXPECT_EQ(vulkan_runs, 2) << variant.dump();
  }
}

}  // namespace
}  // namespace penumbra::testing
