// `penumbra eval` of an atlas variant on an engine's atlas (--map-tile) and
// of an array variant on an engine's array (--map-layer): the light's map as
// one tile or layer among others reads as the same map alone, on the device
// and in the reference, and a bad tile or layer is exit 2.
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
     "map_layout": ["single", "atlas", "array"]}
  ]})";

// Where the fixture's map lies in the atlas: away from every edge, at no
// multiple of its size. In the array: layer 2 of 4.
constexpr int kX = 40;
constexpr int kY = 24;
constexpr int kLayer = 2;
constexpr int kLayers = 4;

class EvalLayout : public EvalFixture {
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
    FloatImage array(map_.width, map_.height * kLayers, 1, 2.0f);
    for (int j = 0; j < map_.height; ++j) {
      for (int i = 0; i < map_.width; ++i) array.at(i, kLayer * map_.height + j) = map_.at(i, j);
    }
    ASSERT_TRUE(write_pfm(dir_->path() / "array.pfm", array).ok());
  }
  static void TearDownTestSuite() { tear_down_eval(); }

  static std::string tile() {
    return "--map-tile " + std::to_string(kX) + "," + std::to_string(kY) + "," +
           std::to_string(map_.width) + "," + std::to_string(map_.height);
  }
  static std::string layer() {
    return "--map-layer " + std::to_string(kLayer) + "," + std::to_string(kLayers);
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

  // The `layout` twin of pcss_b16_p16_whitepaper16 reading LAYOUT.pfm at
  // `place`: its reference is the map alone's, value for value (returned,
  // its marks left in amb.pfm), and the device agrees with it within PCSS's
  // tolerance at `precision` wherever the reference is sure.
  static FloatImage expect_as_alone(const std::string& layout, const std::string& place,
                                    const reference::SamplingPrecision& precision) {
    const std::string single = "pcss_b16_p16_whitepaper16";
    const std::string variant = single + "_" + layout;
    const std::string map = layout + ".pfm";
    const FloatImage alone = eval(single, "depth.pfm", "--reference");
    const FloatImage reference =
        eval(variant, map, place + " --reference --ambiguous " + path("amb.pfm"));
    EXPECT_TRUE(alone.data == reference.data);
    const FloatImage marks = read_pfm(dir_->path() / "amb.pfm").value();
    const FloatImage device = eval(variant, map, place);
    expect_agreement(device, reference, marks, reference::tolerance(Technique::pcss, precision));
    return reference;
  }
};

// The reference on the tile is the reference on the map alone; the device
// reading the tile agrees with it within PCSS's tolerance wherever the
// reference is sure.
TEST_F(EvalLayout, TheTileReadsAsTheMapAlone) {
  reference::SamplingPrecision precision;
  precision.coordinate_error =
      reference::atlas_coordinate_error(map_.width + 2 * kX, map_.height + 2 * kY);
  expect_as_alone("atlas", tile(), precision);
}

// The same of a layer, which is read at its own coordinates: the precision
// of a map alone.
TEST_F(EvalLayout, TheLayerReadsAsTheMapAlone) {
  const FloatImage reference = expect_as_alone("array", layer(), {});
  const std::string array = "pcss_b16_p16_whitepaper16_array";
  const FloatImage marks = read_pfm(dir_->path() / "amb.pfm").value();
  // Without --map-layer the map is the array's one layer.
  const FloatImage one = eval(array, "depth.pfm", "");
  expect_agreement(one, reference, marks, reference::tolerance(Technique::pcss, {}));
}

// A tile outside the map, a malformed one, or one for a variant that reads
// a map of its own is exit 2, names --map-tile and leaves the output intact;
// likewise a layer and --map-layer.
TEST_F(EvalLayout, ABadTileOrLayerIsExit2AndLeavesTheOutputIntact) {
  ASSERT_TRUE(write_pfm(dir_->path() / "kept.pfm", FloatImage(2, 2, 1, 0.25f)).ok());
  const std::string kept = read_file(dir_->path() / "kept.pfm").value();
  struct Case {
    std::string variant;
    std::string map;
    std::string place;
    std::string message;
  };
  const std::string atlas = "pcss_b16_p16_whitepaper16_atlas";
  const std::string array = "pcss_b16_p16_whitepaper16_array";
  const std::vector<Case> cases = {
      {atlas, "atlas.pfm", "--map-tile 40,24,256,999", "is not inside the 336x304 map"},
      {atlas, "atlas.pfm", "--map-tile -1,0,8,8", "x >= 0"},
      {atlas, "atlas.pfm", "--map-tile 0,0,0,8", "width and height >= 1"},
      {atlas, "atlas.pfm", "--map-tile 1,2,3", "expected x,y,width,height"},
      {atlas, "atlas.pfm", "--map-tile 1,2,3,4x", "expected x,y,width,height"},
      {"pcss_b16_p16_whitepaper16", "atlas.pfm", tile(),
       "reads a map of its own (map_layout single)"},
      {array, "atlas.pfm", tile(),
       "reads map_layout array; allowed only for a variant with "
       "map_layout atlas"},
      {array, "array.pfm", "--map-layer 4,4", "does not name a layer of the 1024 rows"},
      {array, "array.pfm", "--map-layer 0,3", "count >= 1 dividing 1024"},
      {array, "array.pfm", "--map-layer 1", "expected layer,count"},
      {array, "array.pfm", layer() + " " + tile(), "cannot be given with --map-tile"},
      {atlas, "array.pfm", layer(),
       "reads map_layout atlas; allowed only for a variant with "
       "map_layout array"}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.variant + " " + c.place);
    const std::string option = c.place.substr(0, c.place.find(' '));
    for (const char* mode : {"", " --reference"}) {
      const CliRun run = run_penumbra(
          "eval '" + lib().string() + "' " + c.variant + " --shadow-map " + path(c.map) +
          " --receivers " + path("recv.pfm") + " -o " + path("kept.pfm") + " " + c.place + mode);
      EXPECT_EQ(run.exit_code, 2) << run.err;
      EXPECT_THAT(run.err, HasSubstr(option));
      EXPECT_THAT(run.err, HasSubstr(c.message));
      EXPECT_EQ(read_file(dir_->path() / "kept.pfm").value(), kept) << "the output changed";
    }
  }
}

}  // namespace
}  // namespace penumbra::testing
