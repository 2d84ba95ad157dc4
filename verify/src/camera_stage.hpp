// The report's stage, or one cascade of the cascaded stage, as the
// engine-form checks see it (function_form.cpp, deferred_mask.cpp): through
// its camera, on the map the target's depth pass drew, and the judging of a
// picture of it.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "backend.hpp"
#include "penumbra/reference/stage.hpp"
#include "penumbra/verify/function_form.hpp"
#include "penumbra/verify/stage_picture.hpp"
#include "scene_fixture.hpp"
#include "scene_truths.hpp"

namespace penumbra {

struct CameraStage {
  reference::Stage stage;
  reference::StageView view;  // the camera's pixels, row 0 at the top
  SceneFixture fixture;       // the stage's scene, its map drawn by the target's depth pass
  PassReflection depth;       // that depth pass's reflection
  int width = 0;
  int height = 0;
};

// The report's stage for `entry`'s checks on `target` (its view and ray
// cast from `truths`), its map drawn on `engine` into a `map_format` depth
// image where prepare_scene() allows. With `cascade`, the cascaded stage
// as that cascade's map sees it (reference::cascade_stage()), its map in
// layer `cascade` of one per cascade, or tile `cascade` of as many. Errors:
// loading or running the depth pass.
Result<CameraStage> camera_stage(Engine& engine, SceneTruths& truths, const Library& library,
                                 const LibraryVariant& entry, Target target, DepthFormat map_format,
                                 std::optional<int> cascade = {});

// The stages verify draws `variant`'s engine forms on: the report's (none),
// then, for a directional light's variant (the orthographic encoding) in an
// atlas or an array, as engines keep their cascades, each cascade of the
// cascaded stage.
std::vector<std::optional<int>> engine_form_stages(const Variant& variant);

// The report's stage per depth pass and encoding, drawn once for every
// engine-form check that reads it (camera_stage() of the first entry that
// asks), as the scenes are drawn once per target; used from the device
// thread only. A stage that cannot be drawn is not kept: each check asking
// for it gets the error.
class CameraStages {
 public:
  // Maps drawn on `engine` into `map_format` depth images where
  // prepare_scene() allows.
  CameraStages(Engine& engine, DepthFormat map_format) : engine_(engine), map_format_(map_format) {}

  // camera_stage(engine, truths, library, entry, target, map_format,
  // cascade), or the one already drawn with the same depth pass files,
  // encoding, layout and cascade.
  Result<const CameraStage*> get(const Library& library, const LibraryVariant& entry, Target target,
                                 std::optional<int> cascade = {});

 private:
  Engine& engine_;
  DepthFormat map_format_;
  SceneTruths truths_;
  std::map<std::string, CameraStage> stages_;
};

// A check of `entry` on `target` by `backend` (on `cascade`'s stage), its
// results to come.
EngineFormCheck started_check(const LibraryVariant& entry, Target target, const Backend& backend,
                              std::optional<int> cascade);

// The receivers a GPU may have used where it computed `exact` (3 channels: u,
// v, z_r) in float32, in its own order and each pixel on its own: they may lie
// further from `exact` than `rounded`'s (the shader's operations emulated in
// float32) do, up to four times the largest of their errors and of `nudged`'s
// (the receivers of a screen_uv interpolated a few ulps off the pixel's centre;
// on lavapipe, up to twice), or of one float32 ulp where all of them round to
// `exact`; or up to `error_bound` (a bound on any float32 evaluation, per
// channel) where that is further: the orders emulated may happen to land near
// `exact`. The bounds are `exact` moved that far. A technique without
// receiver_plane reads each pixel's receiver alone, which lies in the box whose
// eight corners (each channel moved up or down) bound it; for an exact count
// (tolerance 0) the box's 3x3x3 lattice but its centre, since a count's corners
// may agree while inside the box one term has entered and another not yet left.
// receiver_plane's slope is a difference of neighbours, so its bounds take each
// mix of signs over a 2x2 quad, which tilts the screen derivatives every way.
std::vector<FloatImage> receiver_bounds(const Variant& variant, const FloatImage& exact,
                                        std::span<const FloatImage> rounded,
                                        std::span<const FloatImage> nudged,
                                        const FloatImage& error_bound);

// `check`'s results: `visibility` (channel `channel`) against the reference
// at `receivers` on the map the picture read (`own_stored_depth`, or the
// fixture's), with `rounded` and `references` as check_stage_picture()
// takes them. Errors: the reference's.
Status judge_picture(EngineFormCheck& check, Engine& engine, const LibraryVariant& entry,
                     const CameraStage& camera, const std::shared_ptr<const FloatImage>& own_map,
                     const FloatImage& receivers, const FloatImage& visibility, int channel,
                     const RoundedReceivers& rounded = {}, PictureReferences* references = nullptr);

}  // namespace penumbra
