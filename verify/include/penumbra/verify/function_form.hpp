// A variant's engine forms executed as an engine uses them: the function
// form (docs/function-form.md), called by an engine-like vertex and
// fragment stage of the target's language that draw the report's stage
// from its camera, and the deferred pass (docs/deferred-mask.md), run over
// the camera's depth of that stage. Each is checked against the CPU
// reference on the receivers the GPU derived.
#pragma once

#include <optional>

#include "penumbra/library/library.hpp"
#include "penumbra/model/depth_format.hpp"
#include "penumbra/reference/compare.hpp"
#include "penumbra/verify/library_programs.hpp"
#include "penumbra/verify/stage_picture.hpp"
#include "penumbra/vulkan/engine.hpp"

namespace penumbra {

struct EngineFormCheck {
  std::string variant;
  Target target = Target::glsl450;
  std::string backend = "vulkan";  // the path that ran it (verify.json's backend)
  // On the cascaded stage, the cascade it was called for (its map that
  // cascade's layer or tile); none on the report's stage.
  std::optional<int> cascade;
  Execution execution;  // how the shaders reached the device
  std::string error;    // why it could not run (verify_library's checks)
  // The depth image the map was read from: an encoded map's D24 or D16 on
  // the paths that read the Vulkan engine's map (docs/verification.md).
  DepthFormat map_format = DepthFormat::d32_float;
  // The visibility against the reference evaluated on the receivers the
  // GPU called the function with (u, v and z_r from the clip position it
  // wrote) or, for the deferred pass, rebuilt from the camera's depth as
  // the pass does, on the map the target's depth pass drew: over the pixels
  // whose 2x2 quad lies on one face of the stage.
  reference::Comparison comparison;
  std::size_t surface_pixels = 0;  // those pixels, compared or ambiguous
  // Of the pixels where the camera's ray cast hits a surface, the fraction
  // whose GPU receiver is the ray cast's (within 1e-3 in u, v and z_r / z):
  // the camera, the light matrix and the rows agree with the reference's.
  double camera_agreement = 0.0;
  bool pass = false;     // comparison.pass and camera_agreement >= kMinCameraAgreement
  double seconds = 0.0;  // drawing the map and the stage, and checking them
};

// `entry`'s function form for `target` (a text target), on `engine`: the
// map drawn by the target's depth pass, the stage's boxes and ground drawn
// by engine shaders compiled with the target's front end, writing each
// pixel's light clip position and visibility. Errors: bad_input
// when the library has no function form for `target`; a front end's or the
// engine's error. `map_format`: the map's depth image, as prepare_scene()
// takes it (an encoded map's D24 or D16).
Result<EngineFormCheck> check_function_form(Engine& engine, const Library& library,
                                            const LibraryVariant& entry, Target target,
                                            DepthFormat map_format = DepthFormat::d32_float);

// `entry`'s deferred pass for `target` on `engine`: the map drawn by the
// target's depth pass, the report's stage seen by its camera as a depth
// buffer in `target`'s conventions (reversed-Z with a reversed-Z map), and
// the pass rebuilding each pixel's receiver from it with the matrices in
// ShadowParams. Errors: bad_input when the library has no deferred pass for
// `target`; a front end's or the engine's error. `map_format` as
// check_function_form()'s.
Result<EngineFormCheck> check_deferred_mask(Engine& engine, const Library& library,
                                            const LibraryVariant& entry, Target target,
                                            DepthFormat map_format = DepthFormat::d32_float);

}  // namespace penumbra
