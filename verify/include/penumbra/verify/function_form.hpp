// A variant's function form executed as an engine's own shaders call it
// (docs/function-form.md): the report's stage drawn from its camera by an
// engine-like vertex and fragment stage of the target's language, the
// fragment calling penumbra_visibility() with the light clip-space position,
// checked against the CPU reference on the receivers the GPU interpolated.
#pragma once

#include "penumbra/compiler/library.hpp"
#include "penumbra/reference/compare.hpp"
#include "penumbra/verify/stage_picture.hpp"
#include "penumbra/vulkan/engine.hpp"
#include "penumbra/vulkan/library_programs.hpp"

namespace penumbra {

struct FunctionFormCheck {
  std::string variant;
  Target target = Target::glsl450;
  std::string backend = "vulkan";  // the path that ran it (verify.json's backend)
  Execution execution;             // the front end that compiled the engine's shaders
  std::string error;               // why it could not run (verify_library's checks)
  // The visibility against the reference evaluated on the receivers the
  // GPU called the function with (u, v and z_r from the clip position it
  // wrote), on the map the target's depth pass drew: over the pixels whose
  // 2x2 quad lies on one face of the stage (docs/function-form.md).
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
// engine's error.
Result<FunctionFormCheck> check_function_form(Engine& engine, const Library& library,
                                              const LibraryVariant& entry, Target target);

}  // namespace penumbra
