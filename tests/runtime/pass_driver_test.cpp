// The pass driver against a device that records its calls: which passes it
// draws, at what size, offered what, with which size parameters; what it
// gathers and releases; and its errors. Every technique's pass list, and
// pass lists no technique has.
#include "penumbra/runtime/pass_driver.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "penumbra/model/model.hpp"
#include "penumbra/support/minmax_levels.hpp"

namespace penumbra::runtime {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::UnorderedElementsAre;

struct Recorded {
  Draw draw;
  Texture target;
};

// Hands out textures of the sizes asked and records every call.
class RecordingDevice final : public Device {
 public:
  Result<Texture> upload(TextureId as, const FloatImage& image) override {
    uploads.push_back(as);
    return make(image.width, image.height);
  }
  Result<Drawn> draw(const Draw& draw) override {
    if (fail_at == draws.size()) return make_error(Error::Kind::device, draw.where, "lost");
    Texture target = make(draw.width, draw.height);
    draws.push_back({draw, target});
    return Drawn{target, 0.5};
  }
  Result<Texture> gather_mip(Texture map, std::span<const Texture> levels) override {
    gathered_map = map;
    gathered_levels.assign(levels.begin(), levels.end());
    return make(map.width, map.height);
  }
  Result<std::vector<FloatImage>> read_all(std::span<const Texture> textures) override {
    ++read_calls;
    std::vector<FloatImage> images;
    for (Texture texture : textures) images.emplace_back(texture.width, texture.height, 1);
    return images;
  }
  void release(Texture texture) override { released.push_back(texture.id); }

  std::vector<TextureId> uploads;
  std::vector<Recorded> draws;
  std::optional<Texture> gathered_map;
  std::vector<Texture> gathered_levels;
  std::vector<int> released;
  int read_calls = 0;
  std::size_t fail_at = static_cast<std::size_t>(-1);  // the draw that fails

 private:
  Texture make(int width, int height) { return Texture{next_id_++, width, height}; }
  int next_id_ = 1;
};

// A program per pass kind, its id the kind's number plus 100.
PassPrograms all_programs() {
  PassPrograms programs;
  for (PassKind pass : kAllPassKinds) programs[pass] = Program{100 + static_cast<int>(pass)};
  return programs;
}

std::vector<PassKind> drawn_passes(const RecordingDevice& device) {
  std::vector<PassKind> out;
  for (const Recorded& r : device.draws) out.push_back(*r.draw.pass);
  return out;
}

const std::array<std::array<float, 3>, 3> kCasters = {{{0, 0, 0.5f}, {1, 0, 0.5f}, {0, 1, 0.5f}}};

struct Scene {
  RecordingDevice device;
  PassInputs inputs;

  Scene() {
    inputs.casters = kCasters;
    inputs.map_width = 5;
    inputs.map_height = 3;
    inputs.receivers = *device.upload(TextureId::receivers, FloatImage(7, 4, 4));
    inputs.camera_depth = *device.upload(TextureId::camera_depth, FloatImage(6, 2, 1));
    inputs.scene_colour = *device.upload(TextureId::scene_colour, FloatImage(7, 4, 4));
    inputs.params["light"] = {1, 2, 3, 4};
  }
};

// A list no technique has: the mip built, the deferred pass's screen blurred
// once and composited.
TEST(PassDriver, RunsAMadeUpPassListAsTheModelDescribesEachPass) {
  Scene scene;
  scene.inputs.receivers.reset();  // the deferred pass's screen: the camera's depth
  const PassKind list[] = {PassKind::depth,    PassKind::minmax_init, PassKind::minmax_reduce,
                           PassKind::deferred, PassKind::blur_h,      PassKind::composite};
  auto results = run_passes(scene.device, list, all_programs(), scene.inputs);
  ASSERT_TRUE(results) << results.error().message;
  const auto& draws = scene.device.draws;
  // A 5x3 map has levels 3x2, 2x1 and 1x1: one init and two reduce draws.
  EXPECT_THAT(drawn_passes(scene.device),
              ElementsAre(PassKind::depth, PassKind::minmax_init, PassKind::minmax_reduce,
                          PassKind::minmax_reduce, PassKind::deferred, PassKind::blur_h,
                          PassKind::composite));

  const Recorded& depth = draws[0];
  EXPECT_EQ(depth.draw.program, Program{100 + static_cast<int>(PassKind::depth)});
  EXPECT_EQ(depth.draw.triangles.size(), 3u);
  EXPECT_EQ(depth.draw.width, 5);
  EXPECT_EQ(depth.draw.height, 3);
  EXPECT_TRUE(depth.draw.inputs.empty());
  const Texture map = depth.target;

  EXPECT_THAT(draws[1].draw.inputs, ElementsAre(Offer{TextureId::shadow_depth, map}));
  EXPECT_EQ(draws[1].draw.params.at("source_size"), size_vec4(5, 3));
  EXPECT_EQ(draws[1].draw.params.at("screen_size"), size_vec4(3, 2));
  EXPECT_EQ(draws[2].draw.params.at("source_size"), size_vec4(3, 2));
  EXPECT_EQ(draws[3].draw.params.at("screen_size"), size_vec4(1, 1));
  EXPECT_THAT(draws[3].draw.inputs, ElementsAre(Offer{TextureId::minmax_source, draws[2].target}));
  EXPECT_EQ(draws[3].draw.where, "minmax_reduce pass");
  ASSERT_TRUE(scene.device.gathered_map);
  EXPECT_EQ(*scene.device.gathered_map, map);
  EXPECT_THAT(scene.device.gathered_levels,
              ElementsAre(draws[1].target, draws[2].target, draws[3].target));

  const Recorded& deferred = draws[4];
  EXPECT_EQ(deferred.draw.width, 6);
  EXPECT_EQ(deferred.draw.height, 2);
  EXPECT_EQ(deferred.draw.params.at("screen_size"), size_vec4(6, 2));
  EXPECT_EQ(deferred.draw.params.at("light"), (std::array<float, 4>{1, 2, 3, 4}));
  EXPECT_THAT(
      deferred.draw.inputs,
      UnorderedElementsAre(Offer{TextureId::camera_depth, *scene.inputs.camera_depth},
                           Offer{TextureId::shadow_depth, map}, Offer{TextureId::shadow_cmp, map},
                           Offer{TextureId::shadow_minmax, *results->mip}));
  // Each later full-screen pass reads the one before it.
  EXPECT_THAT(draws[5].draw.inputs, ElementsAre(Offer{TextureId::screen_factor, deferred.target}));
  EXPECT_THAT(draws[6].draw.inputs,
              UnorderedElementsAre(Offer{TextureId::screen_factor, draws[5].target},
                                   Offer{TextureId::scene_colour, *scene.inputs.scene_colour}));

  EXPECT_EQ(results->map, map);
  EXPECT_EQ(results->levels.size(), 3u);
  EXPECT_EQ(results->screen(PassKind::composite), draws[6].target);
  EXPECT_FALSE(results->screen(PassKind::query));
  ASSERT_TRUE(results->gpu_ms);
  EXPECT_DOUBLE_EQ(*results->gpu_ms, 0.5 * 7);
}

TEST(PassDriver, ReleasesWhatItDrewAndNotWhatItWasGiven) {
  Scene scene;
  const PassKind list[] = {PassKind::minmax_init, PassKind::minmax_reduce, PassKind::query};
  scene.inputs.map = *scene.device.upload(TextureId::shadow_depth, FloatImage(4, 4, 1));
  auto results = run_passes(scene.device, list, all_programs(), scene.inputs);
  ASSERT_TRUE(results) << results.error().message;
  release_all(scene.device, *results, scene.inputs);
  std::vector<int> drawn;
  for (const Recorded& r : scene.device.draws) drawn.push_back(r.target.id);
  drawn.push_back(results->mip->id);
  EXPECT_THAT(scene.device.released, UnorderedElementsAre(drawn[0], drawn[1], drawn[2], drawn[3]));
}

class TechniquePasses : public ::testing::TestWithParam<Technique> {};

// Every technique's list, as an engine that takes its own map runs it: one
// draw per pass (a min-max reduce per level), none naming the technique.
TEST_P(TechniquePasses, RunOnAGivenMapWithReceiversAndOnTheCameraDepth) {
  const TechniqueDescription& technique = describe(GetParam());
  for (bool deferred : {false, true}) {
    const std::vector<PassKind> list = select_passes(technique.passes, false, deferred);
    if (deferred && std::ranges::find(list, PassKind::deferred) == list.end()) continue;
    Scene scene;
    scene.inputs.map = *scene.device.upload(TextureId::shadow_depth, FloatImage(8, 8, 1));
    if (deferred) scene.inputs.receivers.reset();
    auto results = run_passes(scene.device, list, all_programs(), scene.inputs);
    ASSERT_TRUE(results) << results.error().message;
    std::vector<PassKind> expected;
    for (PassKind pass : list) {
      const int repeats = pass == PassKind::minmax_reduce ? minmax_top_level(8, 8) - 1 : 1;
      expected.insert(expected.end(), repeats, pass);
    }
    EXPECT_EQ(drawn_passes(scene.device), expected);
    EXPECT_EQ(results->mip.has_value(), technique.reads_minmax);
    for (const Recorded& r : scene.device.draws) {
      EXPECT_THAT(r.draw.where, ::testing::Not(HasSubstr(technique.name)));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllTechniques, TechniquePasses, ::testing::ValuesIn(kAllTechniques),
                         [](const auto& test) { return std::string(describe(test.param).name); });

TEST(PassDriver, SelectsTheDeferredPassInTheQuerysPlace) {
  const PassKind list[] = {PassKind::depth, PassKind::minmax_init, PassKind::minmax_reduce,
                           PassKind::query, PassKind::deferred};
  EXPECT_THAT(select_passes(list, true, false),
              ElementsAre(PassKind::depth, PassKind::minmax_init, PassKind::minmax_reduce,
                          PassKind::query));
  EXPECT_THAT(select_passes(list, false, true),
              ElementsAre(PassKind::minmax_init, PassKind::minmax_reduce, PassKind::deferred));
}

TEST(PassDriver, DrawsASurfaceOfferedTheMapAndItsMip) {
  RecordingDevice device;
  const Texture map{1, 8, 8};
  const Texture mip{2, 4, 4};
  auto drawn = draw_surface(device, Program{7}, kCasters, 16, 9, map, mip, {});
  ASSERT_TRUE(drawn) << drawn.error().message;
  const Draw& draw = device.draws.at(0).draw;
  EXPECT_FALSE(draw.pass);
  EXPECT_EQ(draw.program, Program{7});
  EXPECT_EQ(draw.width, 16);
  EXPECT_EQ(draw.triangles.size(), 3u);
  EXPECT_THAT(draw.inputs,
              ElementsAre(Offer{TextureId::shadow_depth, map}, Offer{TextureId::shadow_cmp, map},
                          Offer{TextureId::shadow_minmax, mip}));
}

struct BadList {
  std::string name;
  std::vector<PassKind> passes;
  bool map = true;
  bool screen = true;
  bool programs = true;
  std::string where;
  std::string message;
};

class PassDriverErrors : public ::testing::TestWithParam<BadList> {};

TEST_P(PassDriverErrors, NameThePassAndWhatItLacks) {
  const BadList& bad = GetParam();
  Scene scene;
  if (bad.map)
    scene.inputs.map = *scene.device.upload(TextureId::shadow_depth, FloatImage(4, 4, 1));
  if (!bad.screen) {
    scene.inputs.receivers.reset();
    scene.inputs.camera_depth.reset();
  }
  auto results = run_passes(scene.device, bad.passes,
                            bad.programs ? all_programs() : PassPrograms{}, scene.inputs);
  ASSERT_FALSE(results);
  EXPECT_EQ(results.error().kind, Error::Kind::bad_input);
  EXPECT_EQ(results.error().where, bad.where);
  EXPECT_THAT(results.error().message, HasSubstr(bad.message));
}

INSTANTIATE_TEST_SUITE_P(
    Lists, PassDriverErrors,
    ::testing::Values(
        BadList{"NoProgram", {PassKind::query}, true, true, false, "query pass", "no program"},
        BadList{
            "NoMap", {PassKind::minmax_init}, false, true, true, "minmax_init pass", "shadow map"},
        BadList{"ReduceFirst",
                {PassKind::minmax_reduce},
                true,
                true,
                true,
                "minmax_reduce pass",
                "no minmax_init"},
        BadList{"NoScreen", {PassKind::query}, true, false, true, "query pass", "screen"}),
    [](const auto& test) { return test.param.name; });

// Only the images some pass of the list reads reach the device.
TEST(PassDriver, UploadsOnlyTheScreenImagesThePassesRead) {
  const FloatImage receivers(4, 4, 4);
  const FloatImage camera(4, 4, 1);
  const FloatImage colour(4, 4, 4);
  const ScreenImages images{&receivers, &camera, &colour};
  RecordingDevice device;
  PassInputs query_only;
  const PassKind query[] = {PassKind::query};
  ASSERT_TRUE(upload_screen(device, images, query, query_only));
  EXPECT_THAT(device.uploads, ElementsAre(TextureId::receivers));
  EXPECT_FALSE(query_only.camera_depth);
  EXPECT_FALSE(query_only.scene_colour);

  PassInputs chain;
  const PassKind blur[] = {PassKind::query, PassKind::blur_h, PassKind::composite};
  ASSERT_TRUE(upload_screen(device, images, blur, chain));
  EXPECT_TRUE(chain.receivers && chain.scene_colour);
  EXPECT_FALSE(chain.camera_depth);
}

// Every screen target comes back, in the order the passes ran, from one read.
TEST(PassDriver, ReadsEveryScreenTargetBack) {
  Scene scene;
  const PassKind list[] = {PassKind::query, PassKind::blur_h, PassKind::blur_v,
                           PassKind::composite};
  scene.inputs.map = *scene.device.upload(TextureId::shadow_depth, FloatImage(4, 4, 1));
  auto outputs = run_and_read(scene.device, list, all_programs(), scene.inputs);
  ASSERT_TRUE(outputs) << outputs.error().message;
  ASSERT_EQ(outputs->targets.size(), 4u);
  EXPECT_EQ(outputs->targets[2].first, PassKind::blur_v);
  EXPECT_EQ(outputs->target(PassKind::composite)->width, 7);
  EXPECT_EQ(outputs->target(PassKind::deferred), nullptr);
  EXPECT_EQ(scene.device.read_calls, 1);
}

TEST(PassDriver, StopsAtTheFirstFailedDraw) {
  Scene scene;
  scene.device.fail_at = 1;
  const PassKind list[] = {PassKind::depth, PassKind::query, PassKind::blur_h};
  auto results = run_passes(scene.device, list, all_programs(), scene.inputs);
  ASSERT_FALSE(results);
  EXPECT_EQ(results.error().kind, Error::Kind::device);
  EXPECT_EQ(results.error().where, "query pass");
  EXPECT_EQ(scene.device.draws.size(), 1u);
}

}  // namespace
}  // namespace penumbra::runtime
