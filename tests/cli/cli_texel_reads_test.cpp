// `penumbra eval --texel-reads`: the query's per-pixel count of shadow-map
// and min-max texels read, from the device; with --reference it is bad usage.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "cli_harness.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/support/pfm.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

constexpr int kKernel = 5;

constexpr const char* kManifest = R"({
  "schema": 1,
  "targets": ["spirv"],
  "sets": [{"technique": ["minmax_pcf"], "kernel": [5]},
           {"technique": ["minmax_pcf"], "kernel": [5], "traversal": ["brute_force"]}]})";

class TexelReadsCommand : public EvalFixture {
 protected:
  static void SetUpTestSuite() { set_up_eval("texel-reads", kManifest); }
  static void TearDownTestSuite() { tear_down_eval(); }

  // The texel reads `variant` writes, or an empty image (with a failure).
  static FloatImage texel_reads(const std::string& variant) {
    const std::string file = variant + "_reads.pfm";
    const CliRun run = run_penumbra(
        eval_args(variant, "-o " + path(variant + "_vis.pfm") + " --texel-reads " + path(file)));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_THAT(run.out, HasSubstr(file));
    auto reads = read_pfm(dir_->path() / file);
    EXPECT_TRUE(reads.ok());
    return reads.ok() ? *reads : FloatImage();
  }
};

// Brute force reads the window's texels inside the map, K^2 away from its
// edges; the traversal reads fewer on average over the same pixels.
TEST_F(TexelReadsCommand, WritesOneCountPerPixelBruteForceReadsTheWholeWindow) {
  const FloatImage brute = texel_reads("minmax_pcf_k5_brute_force");
  const FloatImage tree = texel_reads("minmax_pcf_k5");
  ASSERT_EQ(brute.channels, 1);
  ASSERT_EQ(brute.width, receivers_.width);
  ASSERT_EQ(brute.height, receivers_.height);
  ASSERT_EQ(tree.width, receivers_.width);
  double brute_sum = 0.0, tree_sum = 0.0;
  std::size_t interior = 0;
  for (int j = 0; j < brute.height; ++j) {
    for (int i = 0; i < brute.width; ++i) {
      // The window's columns floor(u W) - 2 .. + 2 inside the 256-texel map.
      const float u = receivers_.at(i, j, 0) * 256.0f;
      const float v = receivers_.at(i, j, 1) * 256.0f;
      if (u < 3.0f || v < 3.0f || u > 252.0f || v > 252.0f) continue;
      ++interior;
      EXPECT_EQ(brute.at(i, j), float(kKernel * kKernel)) << "pixel " << i << ", " << j;
      EXPECT_GE(tree.at(i, j), 1.0f) << "pixel " << i << ", " << j;
      brute_sum += brute.at(i, j);
      tree_sum += tree.at(i, j);
    }
  }
  ASSERT_GT(interior, brute.pixel_count() / 2);
  EXPECT_LT(tree_sum, brute_sum);
}

TEST_F(TexelReadsCommand, WithReferenceIsExit2AndWritesNothing) {
  const CliRun run =
      run_penumbra(eval_args("minmax_pcf_k5", "--reference -o " + path("never.pfm") +
                                                  " --texel-reads " + path("never_reads.pfm")));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("--texel-reads"));
  EXPECT_THAT(run.err, HasSubstr("device"));
  EXPECT_FALSE(std::filesystem::exists(dir_->path() / "never.pfm"));
  EXPECT_FALSE(std::filesystem::exists(dir_->path() / "never_reads.pfm"));
}

// Both outputs or neither: the visibility is not left behind when the texel
// reads cannot be written.
TEST_F(TexelReadsCommand, UnwritableTexelReadsIsExit2AndWritesNeitherFile) {
  const std::filesystem::path missing = dir_->path() / "missing" / "reads.pfm";
  const CliRun run = run_penumbra(eval_args(
      "minmax_pcf_k5", "-o " + path("pair_vis.pfm") + " --texel-reads '" + missing.string() + "'"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr(missing.string()));
  EXPECT_FALSE(std::filesystem::exists(missing));
  for (const auto& entry : std::filesystem::directory_iterator(dir_->path())) {
    EXPECT_EQ(entry.path().filename().string().find("pair_vis"), std::string::npos)
        << entry.path() << " was left behind";
  }
}

// The same file twice, however spelled, is refused before anything runs.
TEST_F(TexelReadsCommand, TexelReadsOntoTheVisibilityFileIsExit2) {
  const CliRun run = run_penumbra(eval_args(
      "minmax_pcf_k5", "-o " + path("same.pfm") + " --texel-reads " + path("missing/../same.pfm")));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("--texel-reads"));
  EXPECT_THAT(run.err, HasSubstr("same file"));
  EXPECT_FALSE(std::filesystem::exists(dir_->path() / "same.pfm"));
}

// verify checks the spirv mip against the CPU mip on every scene and records
// each run's mean texel reads: K^2 at most for brute force, fewer for the mip.
TEST_F(TexelReadsCommand, VerifyChecksTheMipAndRecordsTexelReads) {
  const CliRun run = run_penumbra("verify '" + lib().string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_THAT(run.out, HasSubstr("PASS min-max mip [spirv] on steps"));
  std::ifstream in(lib() / "verify.json");
  const nlohmann::json report = nlohmann::json::parse(in);
  std::filesystem::remove(lib() / "verify.json");
  const std::size_t scenes = reference::builtin_scenes().size();
  ASSERT_EQ(report.at("minmax_mip").size(), scenes);
  for (const auto& check : report.at("minmax_mip")) {
    EXPECT_TRUE(check.at("pass").get<bool>()) << check.dump();
    EXPECT_EQ(check.at("mismatched").get<int>(), 0) << check.dump();
  }
  std::map<std::string, double> reads;
  for (const auto& variant : report.at("variants")) {
    for (const auto& scene : variant.at("runs").at(0).at("scenes")) {
      reads[variant.at("name").get<std::string>() + " " + scene.at("scene").get<std::string>()] =
          scene.at("mean_texel_reads").get<double>();
    }
  }
  ASSERT_EQ(reads.size(), 2 * scenes);
  for (const reference::Scene& scene : reference::builtin_scenes()) {
    const double brute = reads.at("minmax_pcf_k5_brute_force " + scene.name);
    const double tree = reads.at("minmax_pcf_k5 " + scene.name);
    EXPECT_GT(brute, 0.8 * kKernel * kKernel) << scene.name;
    EXPECT_LE(brute, double(kKernel * kKernel)) << scene.name;
    EXPECT_GE(tree, 1.0) << scene.name;
    EXPECT_LT(tree, brute) << scene.name;
  }
}

}  // namespace
}  // namespace penumbra::testing
