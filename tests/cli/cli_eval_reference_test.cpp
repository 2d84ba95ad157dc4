// `penumbra eval --reference` as verify's reference: the target's step cap
// (hlsl_dx9), --ambiguous with each excluded pixel's reasons, and the
// default light, which is index.json's `defaults`.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_harness.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/reference/compare.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/reference/techniques.hpp"
#include "penumbra/support/pfm.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

constexpr const char* kManifest = R"({
  "schema": 1,
  "targets": ["spirv", "hlsl_dx11", "hlsl_dx9"],
  "sets": [
    {"technique": ["pcss", "pcf_poisson"], "blocker_samples": [16], "pcf_samples": [16],
     "disk": ["whitepaper16"]},
    {"technique": ["backprojection"]}
  ]})";

class EvalReference : public EvalFixture {
 protected:
  static void SetUpTestSuite() { set_up_eval("eval-reference", kManifest); }
  static void TearDownTestSuite() { tear_down_eval(); }

  // eval's output `file` for `variant` with `extra` arguments, or an empty
  // image (with a failure).
  static FloatImage eval(const std::string& variant, const std::string& file,
                         const std::string& extra) {
    const CliRun run = run_penumbra(eval_args(variant, "-o " + path(file) + " " + extra));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    auto image = read_pfm(dir_->path() / file);
    EXPECT_TRUE(image.ok()) << file;
    return image.ok() ? *image : FloatImage();
  }

  static const Variant& variant(const std::string& name) {
    static const Library library = load_library(lib()).value();
    return library.find(name)->variant;
  }

  // What verify_library holds `target`'s runs of `name` to on this scene.
  static reference::ReferenceImage verify_reference(const std::string& name, Target target) {
    auto image =
        reference::evaluate_image(variant(name), map_, LightParams{}, receivers_,
                                  reference::SamplingPrecision{}, reference::shader_limits(target));
    EXPECT_TRUE(image.ok()) << image.error().to_string();
    return image.ok() ? *image : reference::ReferenceImage{};
  }

  static std::string file_text(const std::string& name) {
    std::ifstream in(dir_->path() / name, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
};

std::size_t differing_pixels(const FloatImage& a, const FloatImage& b) {
  std::size_t count = 0;
  for (std::size_t p = 0; p < a.data.size(); ++p) count += a.data[p] != b.data[p];
  return count;
}

// hlsl_dx9 caps the walks at 224 steps, and on this scene's wide penumbrae
// the cap binds on backprojection's walk, so hlsl_dx9's reference differs
// from hlsl_dx11's. Each is verify's reference for its target, bit for bit,
// and the hlsl_dx9 text run on the device agrees with its own and not the
// other.
TEST_F(EvalReference, WalksAsTheTargetsShaderDoes) {
  const std::string name = "backprojection";
  const FloatImage dx9 = eval(name, "dx9_ref.pfm", "--reference --target hlsl_dx9");
  const FloatImage dx11 = eval(name, "dx11_ref.pfm", "--reference --target hlsl_dx11");
  ASSERT_EQ(dx9.data.size(), receivers_.pixel_count());
  ASSERT_EQ(dx11.data.size(), receivers_.pixel_count());
  EXPECT_GT(differing_pixels(dx9, dx11), 100u) << "the cap should bind on this scene";
  const reference::ReferenceImage capped = verify_reference(name, Target::hlsl_dx9);
  EXPECT_EQ(dx9.data, capped.visibility.data);
  EXPECT_EQ(dx11.data, verify_reference(name, Target::hlsl_dx11).visibility.data);

  const FloatImage device = eval(name, "dx9_device.pfm", "--target hlsl_dx9");
  const double tolerance =
      reference::tolerance(variant(name).technique, reference::SamplingPrecision{});
  auto own = reference::compare(device, dx9, capped.ambiguous, tolerance);
  ASSERT_TRUE(own.ok());
  EXPECT_TRUE(own->pass) << own->over_tolerance << " pixels over, max " << own->max_abs_error;
  auto other = reference::compare(device, dx11, capped.ambiguous, tolerance);
  ASSERT_TRUE(other.ok());
  EXPECT_FALSE(other->pass) << "the device's hlsl_dx9 walk matches the uncapped reference";
}

// `light` as eval's options.
std::string light_args(const LightParams& light) {
  std::ostringstream args;
  args.precision(17);
  args << "--light-size " << light.light_world_size << " --frustum-width " << light.frustum_width
       << " --near " << light.near_plane << " --bias " << light.bias;
  if (light.filter_radius_uv) args << " --filter-radius " << *light.filter_radius_uv;
  return args.str();
}

// The mask is verify's, pixel for pixel, on every built-in scene: 0 where the
// reference decides, else the sum of the codes of the reasons. pcss marks
// point samples at a texel boundary; backprojection under hlsl_dx9's cap,
// close decisions of a walk stopped short and patch edges that may move its
// area too far.
TEST_F(EvalReference, AmbiguousWritesEachExcludedPixelsReasons) {
  const std::pair<std::string, reference::Ambiguity> runs[] = {
      {"pcss_b16_p16_whitepaper16", reference::Ambiguity::texel_boundary},
      {"backprojection", reference::Ambiguity::walk_decision | reference::Ambiguity::area_edges}};
  for (const auto& [name, reasons] : runs) {
    std::map<float, std::size_t> codes;
    for (const reference::Scene& scene : reference::builtin_scenes()) {
      SCOPED_TRACE(name + " on " + scene.name);
      const FloatImage depth =
          reference::ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z);
      const FloatImage recv =
          reference::receivers(scene, scene.receivers_width, scene.receivers_height);
      ASSERT_TRUE(write_pfm(dir_->path() / "scene_depth.pfm", depth).ok());
      ASSERT_TRUE(write_pfm(dir_->path() / "scene_recv.pfm", recv).ok());
      const CliRun run =
          run_penumbra("eval '" + lib().string() + "' " + name + " --shadow-map " +
                       path("scene_depth.pfm") + " --receivers " + path("scene_recv.pfm") + " " +
                       light_args(scene.light) + " --reference --target hlsl_dx9 -o " +
                       path("amb_vis.pfm") + " --ambiguous " + path("amb.pfm"));
      ASSERT_EQ(run.exit_code, 0) << run.err;
      EXPECT_THAT(run.out, HasSubstr("amb.pfm"));
      auto mask = read_pfm(dir_->path() / "amb.pfm");
      ASSERT_TRUE(mask.ok());
      ASSERT_EQ(mask->channels, 1);
      auto expected = reference::evaluate_image(variant(name), depth, scene.light, recv, {},
                                                reference::shader_limits(Target::hlsl_dx9));
      ASSERT_TRUE(expected.ok());
      EXPECT_EQ(mask->data, expected->ambiguous.data);
      for (float code : mask->data) ++codes[code];
    }
    EXPECT_GT(codes.erase(0.0f), 0u) << name;
    // Each of its reasons in some pixels, and no other.
    std::uint8_t seen = 0;
    for (const auto& [code, count] : codes) seen |= std::uint8_t(code);
    EXPECT_EQ(int(seen), int(reasons)) << name;
  }
}

TEST_F(EvalReference, HelpListsTheAmbiguityCodes) {
  const CliRun run = run_penumbra("eval --help");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("--ambiguous"));
  for (const reference::AmbiguityReason& r : reference::kAmbiguityReasons) {
    EXPECT_THAT(run.out, HasSubstr(std::to_string(int(r.reason)) + "  " + r.summary));
  }
}

// --ambiguous without --reference, or onto another of eval's files however
// spelled (relative paths too, run from the scratch directory), is refused
// before anything runs; a mask that cannot be written leaves neither file;
// previous outputs and the inputs stay as they were.
TEST_F(EvalReference, AmbiguousBadUsageIsExit2AndLeavesTheOutputsIntact) {
  std::ofstream(dir_->path() / "kept.pfm") << "previous";
  std::ofstream(dir_->path() / "kept_mask.pfm") << "previous mask";
  const std::string mask = dir_->path().string() + "/kept_mask.pfm";
  const std::string kept = "-o " + path("kept.pfm") + " ";
  const std::string here = "cd " + path("") + " &&";
  struct Case {
    std::string args;
    std::string message;  // the whole of stderr where it ends in a newline
    std::string env = "";
  };
  const Case cases[] = {
      {kept + "--ambiguous '" + mask + "'",
       "penumbra: error: --ambiguous " + mask +
           ": the ambiguity mask is the CPU reference's; allowed only with --reference\n"},
      {kept + "--reference --ambiguous " + path("missing/../kept.pfm"), "--ambiguous"},
      {"-o kept.pfm --reference --ambiguous ./kept.pfm",
       "penumbra: error: --ambiguous ./kept.pfm: is the same file as -o kept.pfm; allowed: a file "
       "of its own\n",
       here},
      {kept + "--reference --ambiguous " + path("depth.pfm"), "--shadow-map"},
      {"-o missing/../depth.pfm --reference --ambiguous kept_mask.pfm", "--shadow-map", here},
      {kept + "--reference --ambiguous '" + (lib() / "mask.pfm").string() + "'", "inside"},
      {"-o missing/../lib/mask.pfm --reference", "inside", here},
      {kept + "--reference --ambiguous " + path("missing/mask.pfm"), "missing/mask.pfm"},
  };
  const std::string depth = file_text("depth.pfm");
  for (const Case& c : cases) {
    SCOPED_TRACE(c.env + " " + c.args);
    const CliRun run = run_penumbra(eval_args("pcss_b16_p16_whitepaper16", c.args), c.env);
    EXPECT_EQ(run.exit_code, 2);
    if (c.message.ends_with("\n")) {
      EXPECT_EQ(run.err, c.message);
    } else {
      EXPECT_THAT(run.err, HasSubstr(c.message));
    }
    EXPECT_EQ(file_text("kept.pfm"), "previous");
    EXPECT_EQ(file_text("kept_mask.pfm"), "previous mask");
    EXPECT_EQ(file_text("depth.pfm"), depth);
    EXPECT_FALSE(std::filesystem::exists(lib() / "mask.pfm"));
  }
}

// eval's light, with no light option given, is index.json's `defaults`: the
// same options spelled out from index.json give the same bytes, on the
// reference and on the device.
TEST_F(EvalReference, DefaultLightIsTheIndexDefaults) {
  std::ifstream in(lib() / "index.json");
  const nlohmann::json defaults = nlohmann::json::parse(in).at("defaults");
  const LightParams light;
  EXPECT_EQ(defaults.at("light_world_size").get<double>(), light.light_world_size);
  EXPECT_EQ(defaults.at("light_frustum_width").get<double>(), light.frustum_width);
  EXPECT_EQ(defaults.at("near_plane").get<double>(), light.near_plane);
  EXPECT_EQ(defaults.at("bias").get<double>(), light.bias);
  EXPECT_EQ(defaults.at("filter_radius_texels").get<double>() / map_.width,
            light.filter_radius(map_.width));
  std::ostringstream spelled;
  spelled.precision(17);
  spelled << "--light-size " << defaults.at("light_world_size").get<double>() << " --frustum-width "
          << defaults.at("light_frustum_width").get<double>() << " --near "
          << defaults.at("near_plane").get<double>() << " --bias "
          << defaults.at("bias").get<double>() << " --filter-radius "
          << defaults.at("filter_radius_texels").get<double>() / map_.width;
  for (const std::string name : {"pcss_b16_p16_whitepaper16", "pcf_poisson_p16_whitepaper16"}) {
    for (const std::string mode : {"--reference", ""}) {
      SCOPED_TRACE(name + " " + mode);
      const CliRun plain = run_penumbra(eval_args(name, mode + " -o " + path("plain.pfm")));
      ASSERT_EQ(plain.exit_code, 0) << plain.err;
      const CliRun given =
          run_penumbra(eval_args(name, mode + " " + spelled.str() + " -o " + path("given.pfm")));
      ASSERT_EQ(given.exit_code, 0) << given.err;
      EXPECT_EQ(file_text("plain.pfm"), file_text("given.pfm"));
    }
  }
}

}  // namespace
}  // namespace penumbra::testing
