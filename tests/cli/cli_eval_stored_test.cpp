// `penumbra eval` on an engine's map as stored (--map-stored, --far) and
// with a mask of pixels that have no receiver (--no-receiver), on the device
// and with --reference.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "cli_harness.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/shadow_params.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/techniques.hpp"
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
     "map_encoding": ["linear", "perspective", "perspective_reversed", "orthographic"]},
    {"technique": ["pcf_grid"], "kernel": [3], "map_encoding": ["perspective"]}
  ]})";

class EvalStored : public EvalFixture {
 protected:
  static void SetUpTestSuite() { set_up_eval("eval-stored", kManifest); }
  static void TearDownTestSuite() { tear_down_eval(); }

  static const LibraryVariant& entry(const std::string& name) {
    static const Library library = load_library(lib()).value();
    const LibraryVariant* found = library.find(name);
    EXPECT_NE(found, nullptr) << name;
    return *found;
  }

  // The fixture's map as an engine's depth buffer stores it for `variant`,
  // drawn with the default near plane and `far`: clamped to the planes
  // (linear z only to the far one), encoded, rounded to float.
  static FloatImage stored(const std::string& variant, double far) {
    const MapEncoding encoding = map_encoding(entry(variant).variant.keys);
    const DepthRange range{LightParams{}.near_plane, far};
    const double nearest = encoding == MapEncoding::linear ? 0.0 : range.near_plane;
    FloatImage out = map_;
    for (float& d : out.data) {
      d = float(encode_depth(encoding, std::clamp(double(d), nearest, far), range));
    }
    return out;
  }

  // The far plane eval picks for the fixture's own map: the power of two
  // at or beyond every depth of the map and the receivers.
  static double evals_own_far() {
    double deepest = 0.0;
    for (float z : map_.data) deepest = std::max(deepest, double(z));
    for (std::size_t p = 0; p < receivers_.pixel_count(); ++p) {
      deepest = std::max(deepest, double(receivers_.data[p * 3 + 2]));
    }
    return 1.0 / double(depth_scale_for(deepest));
  }

  static std::string bytes(const std::string& name) {
    return read_file(dir_->path() / name).value();
  }

  // eval's -o (and with --ambiguous its mask) for `variant` with `extra`.
  static FloatImage eval(const std::string& variant, const std::string& extra,
                         const std::string& map = "depth.pfm") {
    const CliRun run =
        run_penumbra("eval '" + lib().string() + "' " + variant + " --shadow-map " + path(map) +
                     " --receivers " + path("recv.pfm") + " -o " + path("out.pfm") + " " + extra);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    auto image = read_pfm(dir_->path() / "out.pfm");
    return image.ok() ? *image : FloatImage();
  }
  static FloatImage ambiguous() { return read_pfm(dir_->path() / "amb.pfm").value(); }
};

// A map stored in each encoding with eval's own planes reads as eval's own
// encoding of the linear map: the same visibility on the device and in the
// reference, pixel for pixel.
TEST_F(EvalStored, AStoredMapReadsAsEvalsOwnEncoding) {
  const double far = evals_own_far();
  for (const std::string variant :
       {"pcss_b16_p16_whitepaper16", "pcss_b16_p16_whitepaper16_perspective",
        "pcss_b16_p16_whitepaper16_perspective_reversed",
        "pcss_b16_p16_whitepaper16_orthographic"}) {
    SCOPED_TRACE(variant);
    ASSERT_TRUE(write_pfm(dir_->path() / "stored.pfm", stored(variant, far)).ok());
    const std::string stored_args = "--map-stored --far " + std::to_string(far);
    for (const std::string mode : {"", "--reference"}) {
      const FloatImage own = eval(variant, mode);
      const FloatImage engines = eval(variant, mode + " " + stored_args, "stored.pfm");
      ASSERT_EQ(own.data.size(), engines.data.size());
      EXPECT_TRUE(own.data == engines.data) << mode;
    }
  }
}

// An engine's far plane that is no power of two: the device's result on
// the stored texels agrees with the reference on the same texels.
TEST_F(EvalStored, TheReferenceRunsOnTheEnginesTexels) {
  const std::string variant = "pcss_b16_p16_whitepaper16_perspective";
  const double far = 40.0;
  ASSERT_TRUE(write_pfm(dir_->path() / "stored40.pfm", stored(variant, far)).ok());
  const std::string args = "--map-stored --far 40";
  const FloatImage device = eval(variant, args, "stored40.pfm");
  const FloatImage reference =
      eval(variant, args + " --reference --ambiguous " + path("amb.pfm"), "stored40.pfm");
  const FloatImage marks = ambiguous();
  expect_agreement(device, reference, marks,
                   reference::tolerance(Technique::pcss, reference::SamplingPrecision{}));
}

// Pixels the mask marks are lit and marked no_receiver; every other pixel
// is as without the mask.
TEST_F(EvalStored, NoReceiverPixelsAreLitAndMarked) {
  FloatImage mask(receivers_.width, receivers_.height, 1);
  for (int j = 0; j < mask.height / 2; ++j) {
    for (int i = 0; i < mask.width; ++i) mask.at(i, j) = 1.0f;
  }
  ASSERT_TRUE(write_pfm(dir_->path() / "mask.pfm", mask).ok());
  const std::string masked = "--no-receiver " + path("mask.pfm");
  const auto no_receiver = float(std::uint16_t(reference::Ambiguity::no_receiver));
  for (const std::string variant : {"pcss_b16_p16_whitepaper16", "pcf_grid_k3_perspective"}) {
    SCOPED_TRACE(variant);
    for (const bool reference : {false, true}) {
      const std::string mode = reference ? "--reference --ambiguous " + path("amb.pfm") : "";
      const FloatImage plain = eval(variant, mode);
      const FloatImage plain_marks = reference ? ambiguous() : FloatImage();
      const FloatImage out = eval(variant, mode + " " + masked);
      const FloatImage marks = reference ? ambiguous() : FloatImage();
      ASSERT_EQ(out.data.size(), plain.data.size());
      std::size_t shadowed = 0;
      for (std::size_t p = 0; p < out.data.size(); ++p) {
        if (mask.data[p] != 0.0f) {
          ASSERT_EQ(out.data[p], 1.0f) << "pixel " << p;
          shadowed += plain.data[p] < 1.0f;
          if (reference) {
            ASSERT_EQ(marks.data[p], no_receiver) << "pixel " << p;
          }
        } else {
          ASSERT_EQ(out.data[p], plain.data[p]) << "pixel " << p;
          if (reference) {
            ASSERT_EQ(marks.data[p], plain_marks.data[p]) << "pixel " << p;
          }
        }
      }
      EXPECT_GT(shadowed, 100u) << "the mask must cover shadowed receivers";
    }
  }
}

// Bad --map-stored, --far and --no-receiver input is exit 2, names the
// argument, and leaves the previous output as it was.
TEST_F(EvalStored, BadStoredMapOrMaskIsExit2AndLeavesTheOutputIntact) {
  FloatImage beyond = stored("pcss_b16_p16_whitepaper16_perspective", 40.0);
  ASSERT_TRUE(write_pfm(dir_->path() / "s40.pfm", beyond).ok());
  beyond.at(3, 5) = 1.5f;
  ASSERT_TRUE(write_pfm(dir_->path() / "beyond.pfm", beyond).ok());
  ASSERT_TRUE(write_pfm(dir_->path() / "small-mask.pfm", FloatImage(4, 4, 1)).ok());
  ASSERT_TRUE(write_pfm(dir_->path() / "kept.pfm", FloatImage(2, 2, 1, 0.25f)).ok());
  const std::string kept = bytes("kept.pfm");
  struct Case {
    std::string args;
    std::string message;
  };
  const std::string depth = " --shadow-map " + path("depth.pfm");
  const std::vector<Case> cases = {
      {depth + " --map-stored", "--map-stored"},
      {depth + " --far 40", "--far"},
      {depth + " --map-stored --far 40", "a stored map (--map-stored) holds depth-buffer values"},
      {" --shadow-map " + path("beyond.pfm") + " --map-stored --far 40", "texel (3, 5) holds 1.5"},
      {" --shadow-map " + path("s40.pfm") + " --map-stored --far 5", "--far 5"},
      {depth + " --no-receiver " + path("small-mask.pfm"), "--no-receiver"},
      {depth + " --no-receiver " + path("kept.pfm"), "--no-receiver"}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    for (const char* mode : {"", " --reference"}) {
      const CliRun run = run_penumbra(
          "eval '" + lib().string() + "' pcss_b16_p16_whitepaper16_perspective" + c.args +
          " --receivers " + path("recv.pfm") + " -o " + path("kept.pfm") + mode);
      EXPECT_EQ(run.exit_code, 2) << run.err;
      EXPECT_THAT(run.err, HasSubstr(c.message));
      EXPECT_EQ(bytes("kept.pfm"), kept) << "the output changed";
    }
  }
}

}  // namespace
}  // namespace penumbra::testing
