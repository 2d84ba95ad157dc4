// An engine's own shaders around a variant's function form
// (docs/function-form.md), written in each text target's language: a vertex
// stage that places the report's stage in a camera and hands the fragment
// its light clip-space position, and a fragment stage that pastes or
// includes the function form and calls penumbra_visibility().
#pragma once

#include <array>
#include <string>

#include "penumbra/model/model.hpp"
#include "penumbra/model/target_reflection.hpp"
#include "penumbra/reference/stage.hpp"

namespace penumbra {

// Rows of a 4x4 matrix.
using Matrix4 = std::array<std::array<double, 4>, 4>;

// The camera of `stage` seeing light-view positions through `width` x
// `height` pixel centres exactly as reference::view() casts its rays: row 0
// at the picture's top, in `target`'s clip space (y = -1 on row 0 for the
// GL targets, whose first row in memory is at the window's y = -1; +1 for
// Direct3D's; z in [-w, w] for GL, [0, w] for Direct3D).
Matrix4 camera_clip(const reference::Stage& stage, int width, int height, Target target);

// The light's view-projection for the function form: x and y scaled by
// 2 n / Fw (y negated for Direct3D, whose viewport puts +1 on the map's
// first row), w = z.
Matrix4 light_clip(const reference::LightParams& light, Target target);

// Whether the function form `reflection` describes takes the pixel (the
// `rotation` key).
bool takes_pixel(const PassReflection& reflection);

// What the vertex stage hands on besides the light clip position.
struct VertexOptions {
  // The function takes the pixel: on Direct3D 9 the vertex stage then
  // writes the pixel's position in the width x height picture, times w
  // (TEXCOORD1), as engines of that API compute it: ps_3_0's VPOS is what
  // vkd3d's d3dbc translator cannot read.
  bool pass_pixel = false;
  int width = 0;
  int height = 0;
  // Direct3D 9's runtime samples pixels at integer window coordinates: the
  // position moves half a pixel so that they see what the other APIs'
  // pixel centres do (docs/engines/d3d9.md).
  bool half_pixel_offset = false;
};

// The vertex stage: position (light-view space, vec3) in at location 0 /
// TEXCOORD0, gl_Position = camera * position, light_clip_position out.
std::string engine_vertex_shader(Target target, const Matrix4& camera, const Matrix4& light,
                                 const VertexOptions& options);

// The fragment stage around `function_text` (the function form's file),
// declared as its `reflection` says. Output 0 is the light clip position it
// called penumbra_visibility() with, its z (which the function does not
// read) replaced by the visibility: (x, y, visibility, w).
std::string engine_fragment_shader(Target target, const PassReflection& reflection,
                                   const std::string& function_text);

}  // namespace penumbra
