// `penumbra eval` and `penumbra verify` end to end through the binary, on a
// small library built by `penumbra build`.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "cli_harness.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/reference/compare.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/reference/whitepaper_pcss.hpp"
#include "penumbra/support/pfm.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

constexpr const char* kManifest = R"({
  "schema": 1,
  "targets": ["spirv", "glsl450", "hlsl_dx9"],
  "sets": [
    {"technique": ["pcss"], "blocker_samples": [16], "pcf_samples": [16], "disk": ["whitepaper16"]},
    {"technique": ["hard"]},
    {"technique": ["pcf_grid"], "kernel": [3]}
  ]})";

class EvalCommand : public EvalFixture {
 protected:
  static void SetUpTestSuite() { set_up_eval("eval", kManifest); }
  static void TearDownTestSuite() { tear_down_eval(); }
};

TEST_F(EvalCommand, PcssWhitepaper16AgreesWithTheWhitepapersCode) {
  const CliRun run = run_penumbra(eval_args("pcss_b16_p16_whitepaper16", "-o " + path("vis.pfm")));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto vis = read_pfm(dir_->path() / "vis.pfm");
  ASSERT_TRUE(vis.ok()) << vis.error().to_string();
  ASSERT_EQ(vis->width, receivers_.width);
  ASSERT_EQ(vis->channels, 1);

  // Pixels whose point samples sit on a texel boundary may differ legitimately.
  auto library = load_library(lib());
  ASSERT_TRUE(library.ok());
  const reference::SamplingPrecision precision;
  auto ref = reference::evaluate_image(library->find("pcss_b16_p16_whitepaper16")->variant, map_,
                                       LightParams{}, receivers_, precision);
  ASSERT_TRUE(ref.ok());
  const reference::ShadowMapView view(map_);
  const double tolerance = reference::tolerance(Technique::pcss, precision);
  std::size_t compared = 0, partial = 0;
  for (int j = 0; j < vis->height; ++j) {
    for (int i = 0; i < vis->width; ++i) {
      if (ref->ambiguous.at(i, j) != 0.0f) continue;
      const double expected = reference::whitepaper_pcss(
          view, receivers_.at(i, j, 0), receivers_.at(i, j, 1), receivers_.at(i, j, 2));
      ASSERT_NEAR(vis->at(i, j), expected, tolerance) << "pixel " << i << ", " << j;
      ++compared;
      if (expected > 0.01 && expected < 0.99) ++partial;
    }
  }
  EXPECT_GT(compared, vis->pixel_count() * 9 / 10);
  EXPECT_GT(partial, 500u) << "the scene must have real penumbrae";
}

// A receiver exactly at the stored depth is lit (LESS_EQUAL); one ulp behind
// it is shadowed. Checked on the device and in the reference, through the
// point compare (hard) and the bilinear compare (pcf_grid).
TEST_F(EvalCommand, ReceiverAtTheStoredDepthIsLitAndOneUlpBehindIsNot) {
  const float depth = 12.0f;
  const FloatImage map(16, 16, 1, depth);
  FloatImage recv(4, 2, 3);
  for (int j = 0; j < recv.height; ++j) {
    for (int i = 0; i < recv.width; ++i) {
      recv.at(i, j, 0) = (float(i) * 3.0f + 2.3f) / 16.0f;
      recv.at(i, j, 1) = (float(j) * 7.0f + 4.6f) / 16.0f;
      recv.at(i, j, 2) = j == 0 ? depth : std::nextafter(depth, 100.0f);
    }
  }
  ASSERT_TRUE(write_pfm(dir_->path() / "flat.pfm", map).ok());
  ASSERT_TRUE(write_pfm(dir_->path() / "edge_recv.pfm", recv).ok());
  for (const std::string variant : {"hard", "pcf_grid_k3"}) {
    for (const std::string mode : {"", "--reference"}) {
      const CliRun run = run_penumbra(
          "eval '" + lib().string() + "' " + variant + " --shadow-map " + path("flat.pfm") +
          " --receivers " + path("edge_recv.pfm") + " " + mode + " -o " + path("edge.pfm"));
      ASSERT_EQ(run.exit_code, 0) << run.err;
      auto vis = read_pfm(dir_->path() / "edge.pfm");
      ASSERT_TRUE(vis.ok());
      for (int i = 0; i < recv.width; ++i) {
        EXPECT_EQ(vis->at(i, 0), 1.0f) << variant << " " << mode << " at z_r == depth";
        EXPECT_EQ(vis->at(i, 1), 0.0f) << variant << " " << mode << " one ulp behind";
      }
    }
  }
}

TEST_F(EvalCommand, ReferenceFlagRunsTheCpuReference) {
  const CliRun run = run_penumbra(eval_args("hard", "--reference -o " + path("hard_ref.pfm")));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  auto vis = read_pfm(dir_->path() / "hard_ref.pfm");
  ASSERT_TRUE(vis.ok());
  double lit = 0;
  for (float v : vis->data) lit += v;
  EXPECT_GT(lit, 0.0);
  EXPECT_LT(lit, static_cast<double>(vis->pixel_count()));
}

TEST_F(EvalCommand, MissingShadowMapIsExit2AndWritesNothing) {
  const CliRun run =
      run_penumbra("eval '" + lib().string() + "' hard --shadow-map " + path("absent.pfm") +
                   " --receivers " + path("recv.pfm") + " -o " + path("never.pfm"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("absent.pfm"));
  EXPECT_FALSE(std::filesystem::exists(dir_->path() / "never.pfm"));
}

// An output that is one of eval's inputs, however spelled, is refused before
// anything runs, and the input stays as it was.
TEST_F(EvalCommand, OutputOntoAnInputIsExit2AndLeavesTheInputIntact) {
  const auto inputs = dir_->path() / "inputs";
  std::filesystem::create_directories(inputs);
  std::filesystem::copy_file(dir_->path() / "depth.pfm", inputs / "depth.pfm");
  std::filesystem::copy_file(dir_->path() / "recv.pfm", inputs / "recv.pfm");
  std::filesystem::create_hard_link(inputs / "recv.pfm", inputs / "recv-link.pfm");
  const auto before = read_tree(inputs);
  const auto lib_before = read_tree(lib());
  const std::string depth = "'" + (inputs / "depth.pfm").string() + "'";
  const std::string recv = "'" + (inputs / "recv.pfm").string() + "'";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"-o " + depth, "--shadow-map"},
      {"-o '" + (inputs / "../inputs/recv.pfm").string() + "'", "--receivers"},
      {"-o '" + (inputs / "recv-link.pfm").string() + "'", "--receivers"},
      {"-o '" + (lib() / "index.json").string() + "'", lib().string()},
      // Its own name: the suite's earlier tests leave their vis.pfm behind.
      {"-o " + path("onto-input.pfm") + " --texel-reads " + depth, "--shadow-map"}};
  for (const auto& [output, names] : cases) {
    SCOPED_TRACE(output);
    for (const char* mode : {"--reference", ""}) {
      const CliRun run = run_penumbra("eval '" + lib().string() + "' hard --shadow-map " + depth +
                                      " --receivers " + recv + " " + output + " " + mode);
      EXPECT_EQ(run.exit_code, 2);
      EXPECT_THAT(run.err, HasSubstr(names));
      EXPECT_THAT(run.err, HasSubstr("allowed:"));
      EXPECT_TRUE(read_tree(inputs) == before) << "an input changed";
      EXPECT_TRUE(read_tree(lib()) == lib_before) << "the library changed";
      EXPECT_FALSE(std::filesystem::exists(dir_->path() / "onto-input.pfm"));
    }
  }
}

TEST_F(EvalCommand, WrongReceiversImageIsExit2) {
  const CliRun run =
      run_penumbra("eval '" + lib().string() + "' hard --shadow-map " + path("depth.pfm") +
                   " --receivers " + path("depth.pfm") + " -o " + path("never.pfm"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("--receivers"));
  EXPECT_FALSE(std::filesystem::exists(dir_->path() / "never.pfm"));
}

// A light option that is NaN, infinite or out of range is refused with one
// line naming the argument and its range, on the device and with
// --reference alike, and a previous output is left as it was.
TEST_F(EvalCommand, LightOptionsOutOfRangeAreExit2AndLeaveTheOutputIntact) {
  {
    std::ofstream previous(dir_->path() / "kept.pfm");
    previous << "previous";
  }
  const std::pair<const char*, const char*> bad[] = {
      {"--light-size nan", "--light-size nan: out of range; allowed: a number from 0 to 1e+06"},
      {"--light-size -1", "--light-size -1: out of range; allowed: a number from 0 to 1e+06"},
      {"--frustum-width inf",
       "--frustum-width inf: out of range; allowed: a number from 1e-06 to 1e+06"},
      {"--near 0", "--near 0: out of range; allowed: a number from 1e-06 to 1e+06"},
      {"--near nan", "--near nan: out of range; allowed: a number from 1e-06 to 1e+06"},
      {"--bias nan", "--bias nan: out of range; allowed: a number from -1e+06 to 1e+06"},
      {"--bias 1e300", "--bias 1e+300: out of range; allowed: a number from -1e+06 to 1e+06"},
      {"--filter-radius nan",
       "--filter-radius nan: out of range; allowed: a number from 1e-06 to 1e+06"},
      {"--filter-radius 0",
       "--filter-radius 0: out of range; allowed: a number from 1e-06 to 1e+06"},
  };
  for (const auto& [option, message] : bad) {
    for (const char* mode : {"", "--reference "}) {
      const CliRun run = run_penumbra(eval_args(
          "pcss_b16_p16_whitepaper16", std::string(mode) + option + " -o " + path("kept.pfm")));
      EXPECT_EQ(run.exit_code, 2) << mode << option;
      EXPECT_EQ(run.err, std::string("penumbra: error: ") + message + "\n") << mode << option;
      std::ifstream kept(dir_->path() / "kept.pfm");
      std::stringstream text;
      text << kept.rdbuf();
      EXPECT_TRUE(text.str() == "previous") << mode << option << ": the output was replaced";
    }
  }
}

TEST_F(EvalCommand, UnknownVariantAndTargetAreExit2) {
  CliRun run = run_penumbra(eval_args("pcss_b99", "-o " + path("never.pfm")));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("pcss_b99"));
  run = run_penumbra(eval_args("hard", "--target metal -o " + path("never.pfm")));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("metal"));
  EXPECT_FALSE(std::filesystem::exists(dir_->path() / "never.pfm"));
}

TEST_F(EvalCommand, VerifyWritesVerifyJsonAndPasses) {
  const CliRun run = run_penumbra("verify '" + lib().string() + "'");
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_THAT(run.out, HasSubstr("PASS pcss_b16_p16_whitepaper16 [spirv]"));
  std::ifstream in(lib() / "verify.json");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_THAT(text.str(), HasSubstr("\"pass\": true"));
  std::filesystem::remove(lib() / "verify.json");
}

// Replaces `from` by `to` in a library file; fails the test if absent.
void edit_file(const std::filesystem::path& file, const std::string& from, const std::string& to) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  std::string body = text.str();
  const auto at = body.find(from);
  ASSERT_NE(at, std::string::npos) << from << " not in " << file;
  body.replace(at, from.size(), to);
  std::ofstream(file) << body;
}

// A wrong emission is caught by executing that target's own text: a changed
// constant in the DX9 HLSL, and GLSL that no longer compiles.
TEST_F(EvalCommand, VerifyFailsOnABrokenEmission) {
  const auto broken = dir_->path() / "broken";
  std::filesystem::copy(lib(), broken, std::filesystem::copy_options::recursive);
  const auto variant = std::string("pcss_b16_p16_whitepaper16");
  edit_file(broken / "hlsl_dx9" / variant / "query.frag.hlsl", "(zReceiver - zBlocker) / zBlocker",
            "(zReceiver - zBlocker) / (zBlocker * 0.9f)");
  edit_file(broken / "glsl450" / "hard" / "query.frag", "void main()",
            "void main() { oops; }\nvoid unused()");
  const CliRun run = run_penumbra("verify '" + broken.string() + "' --no-gl");
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  EXPECT_THAT(run.out, HasSubstr("FAIL pcss_b16_p16_whitepaper16 [hlsl_dx9]"));
  EXPECT_THAT(run.out, HasSubstr("FAIL hard [glsl450]"));
  EXPECT_THAT(run.out, HasSubstr("PASS pcss_b16_p16_whitepaper16 [spirv]"));
  EXPECT_THAT(run.out, HasSubstr("PASS pcss_b16_p16_whitepaper16 [glsl450]"));
  EXPECT_THAT(run.out, HasSubstr("PASS hard [hlsl_dx9]"));
  std::ifstream in(broken / "verify.json");
  std::stringstream json;
  json << in.rdbuf();
  EXPECT_THAT(json.str(), HasSubstr("\"pass\": false"));
  EXPECT_THAT(json.str(), HasSubstr("glslang"));  // the run says which front end it used
}

TEST_F(EvalCommand, EvalRunsEachTargetsOwnTextAgainstTheReference) {
  auto library = load_library(lib());
  ASSERT_TRUE(library.ok());
  const Variant& variant = library->find("pcss_b16_p16_whitepaper16")->variant;
  const reference::SamplingPrecision precision;
  auto ref = reference::evaluate_image(variant, map_, LightParams{}, receivers_, precision);
  ASSERT_TRUE(ref.ok());
  for (const std::string target : {"spirv", "glsl450", "hlsl_dx9"}) {
    const CliRun run =
        run_penumbra(eval_args(variant.name, "--target " + target + " -o " + path("t.pfm")));
    ASSERT_EQ(run.exit_code, 0) << target << ": " << run.err;
    auto vis = read_pfm(dir_->path() / "t.pfm");
    ASSERT_TRUE(vis.ok());
    auto comparison = reference::compare(*vis, ref->visibility, ref->ambiguous,
                                         reference::tolerance(Technique::pcss, precision));
    ASSERT_TRUE(comparison.ok());
    EXPECT_TRUE(comparison->pass) << target << ": max error " << comparison->max_abs_error;
  }
}

TEST_F(EvalCommand, NoVulkanDeviceIsExit2) {
  const CliRun run = run_penumbra("verify '" + lib().string() + "' --device no-such-gpu");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("no-such-gpu"));
  EXPECT_FALSE(std::filesystem::exists(lib() / "verify.json"));
  const CliRun none =
      run_penumbra("verify '" + lib().string() + "'", "VK_ICD_FILENAMES=/nonexistent.json");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_THAT(none.err, HasSubstr("Vulkan"));
  EXPECT_FALSE(std::filesystem::exists(lib() / "verify.json"));
}

TEST_F(EvalCommand, MissingLibraryIsExit2) {
  const CliRun run = run_penumbra("verify " + path("nolib"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("index.json"));
}

}  // namespace
}  // namespace penumbra::testing
