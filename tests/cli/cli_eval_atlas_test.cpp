// `penumbra eval` of an atlas variant on an engine's atlas (--map-tile): the
// light's map as one tile among others reads as the same map alone, on the
// device and in the reference, and a bad tile is exit 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_harness.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/support/file.hpp"
#include "penumbra/support/pfm.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

constexpr const char* kManifest = R"({
  "schema": 1,
  "targets": ["spirv", "glsl450"],
  "sets": [
    {"technique": ["pcss"], "blocker_samples": [16], "pcf_samples": [16], "disk": ["whitepaper16"],
     "map_layout": ["single", "atlas"]}
  ]})";

// Where the fixture's map lies in the atlas: away from every edge, at no
// multiple of its size.
constexpr int kX = 40;
constexpr int kY = 24;

class EvalAtlas : public EvalFixture {
 protected:
  static void SetUpTestSuite() {
    set_up_eval("eval-atlas", kManifest);
    // The map among occluders at a quarter of the near plane's depth, which
    // shadow every receiver a read of theirs reached.
    FloatImage atlas(map_.width + 2 * kX, map_.height + 2 * kY, 1, 2.0f);
    for (int j = 0; j < map_.height; ++j) {
      for (int i = 0; i < map_.width; ++i) atlas.at(kX + i, kY + j) = map_.at(i, j);
    }
    ASSERT_TRUE(write_pfm(dir_->path() / "atlas.pfm", atlas).ok());
  }
  static void TearDownTestSuite() { tear_down_eval(); }

  static std::string tile() {
    return "--map-tile " + std::to_string(kX) + "," + std::to_string(kY) + "," +
           std::to_string(map_.width) + "," + std::to_string(map_.height);
  }

  static FloatImage eval(const std::string& variant, const std::string& map,
                         const std::string& extra) {
    const CliRun run =
        run_penumbra("eval '" + lib().string() + "' " + variant + " --shadow-map " + path(map) +
                     " --receivers " + path("recv.pfm") + " -o " + path("out.pfm") + " " + extra);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    auto image = read_pfm(dir_->path() / "out.pfm");
    return image.ok() ? *image : FloatImage();
  }
};

// The reference on the tile is the reference on the map alone; the device
// reading the tile agrees with it within PCSS's tolerance wherever the
// reference is sure.
TEST_F(EvalAtlas, TheTileReadsAsTheMapAlone) {
  const std::string single = "pcss_b16_p16_whitepaper16";
  const std::string atlas = single + "_atlas";
  const FloatImage alone = eval(single, "depth.pfm", "--reference");
  const FloatImage reference =
      eval(atlas, "atlas.pfm", tile() + " --reference --ambiguous " + path("amb.pfm"));
  EXPECT_TRUE(alone.data == reference.data);
  const FloatImage marks = read_pfm(dir_->path() / "amb.pfm").value();
  const FloatImage device = eval(atlas, "atlas.pfm", tile());
  reference::SamplingPrecision precision;
  precision.coordinate_error =
      reference::atlas_coordinate_error(map_.width + 2 * kX, map_.height + 2 * kY);
  expect_agreement(device, reference, marks, reference::tolerance(Technique::pcss, precision));
}

// A tile outside the map, a malformed one, or one for a variant that reads
// a map of its own is exit 2, names --map-tile and leaves the output intact.
TEST_F(EvalAtlas, ABadTileIsExit2AndLeavesTheOutputIntact) {
  ASSERT_TRUE(write_pfm(dir_->path() / "kept.pfm", FloatImage(2, 2, 1, 0.25f)).ok());
  const std::string kept = read_file(dir_->path() / "kept.pfm").value();
  struct Case {
    std::string variant;
    std::string tile;
    std::string message;
  };
  const std::string atlas = "pcss_b16_p16_whitepaper16_atlas";
  const std::vector<Case> cases = {
      {atlas, "--map-tile 40,24,256,999", "is not inside the 336x304 map"},
      {atlas, "--map-tile -1,0,8,8", "x >= 0"},
      {atlas, "--map-tile 0,0,0,8", "width and height >= 1"},
      {atlas, "--map-tile 1,2,3", "expected x,y,width,height"},
      {atlas, "--map-tile 1,2,3,4x", "expected x,y,width,height"},
      {"pcss_b16_p16_whitepaper16", tile(), "reads a map of its own (map_layout single)"}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.variant + " " + c.tile);
    for (const char* mode : {"", " --reference"}) {
      const CliRun run = run_penumbra(
          "eval '" + lib().string() + "' " + c.variant + " --shadow-map " + path("atlas.pfm") +
          " --receivers " + path("recv.pfm") + " -o " + path("kept.pfm") + " " + c.tile + mode);
      EXPECT_EQ(run.exit_code, 2) << run.err;
      EXPECT_THAT(run.err, HasSubstr("--map-tile"));
      EXPECT_THAT(run.err, HasSubstr(c.message));
      EXPECT_EQ(read_file(dir_->path() / "kept.pfm").value(), kept) << "the output changed";
    }
  }
}

}  // namespace
}  // namespace penumbra::testing
