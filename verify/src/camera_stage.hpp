// The report's stage as the engine-form checks see it (function_form.cpp,
// deferred_mask.cpp): through the report's camera, on the map the target's
// depth pass drew, and the judging of a picture of it.
#pragma once

#include <memory>
#include <span>

#include "backend.hpp"
#include "penumbra/reference/stage.hpp"
#include "penumbra/verify/function_form.hpp"
#include "scene_fixture.hpp"

namespace penumbra {

struct CameraStage {
  reference::Stage stage;
  reference::StageView view;  // the camera's pixels, row 0 at the top
  SceneFixture fixture;       // the stage's scene, its map drawn by the target's depth pass
  PassReflection depth;       // that depth pass's reflection
  int width = 0;
  int height = 0;
};

// The report's stage for `entry`'s checks on `target`, its map drawn on
// `engine` into a `map_format` depth image where prepare_scene() allows.
// Errors: loading or running the depth pass.
Result<CameraStage> camera_stage(Engine& engine, const Library& library,
                                 const LibraryVariant& entry, Target target,
                                 DepthFormat map_format);

// A check of `entry` on `target` by `backend`, its results to come.
EngineFormCheck started_check(const LibraryVariant& entry, Target target, const Backend& backend);

// `check`'s results: `visibility` (channel `channel`) against the reference
// at `receivers` on the map the picture read (`own_stored_depth`, or the
// fixture's), with `rounded` as check_stage_picture() takes it. Errors: the
// reference's.
Status judge_picture(EngineFormCheck& check, Engine& engine, const LibraryVariant& entry,
                     const CameraStage& camera, const std::shared_ptr<const FloatImage>& own_map,
                     const FloatImage& receivers, const FloatImage& visibility, int channel,
                     std::span<const FloatImage> rounded = {});

}  // namespace penumbra
