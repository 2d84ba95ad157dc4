// An engine's own shaders around a variant's function form
// (docs/function-form.md), written in each text target's language: a vertex
// stage that places the report's stage in a camera and hands the fragment
// its light clip-space position, and a fragment stage that pastes or
// includes the function form and calls penumbra_visibility().
#pragma once

#include <array>
#include <optional>
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

// How a receiver's linear light-view z comes out of its light clip position
// (shaderlib/common/light_clip.glsl): w for a perspective light; for an
// orthographic one, z / w taken to the depth d in [0, 1] and mixed between
// the planes as the shader does, (1 - d) n + d f.
struct LightClipDepth {
  bool orthographic = false;
  bool zero_to_one = true;  // clip z / w spans [0, 1] (Direct3D, SPIR-V); else [-1, 1]
  double near_plane = 0.0;  // n
  double far_plane = 0.0;   // f

  template <typename Real>
  Real linear_z(Real z, Real w) const {
    if (!orthographic) return w;
    Real d = z / w;
    if (!zero_to_one) d = Real(0.5) * d + Real(0.5);
    return (Real(1) - d) * Real(near_plane) + d * Real(far_plane);
  }
};

// `light`'s clip depth for `target`, its far plane at `far_plane`.
LightClipDepth light_clip_depth(const LightParams& light, double far_plane, Target target);

// The light's view-projection for the function form and the deferred pass:
// x and y scaled by 2 n / Fw (y negated for Direct3D, whose viewport puts +1
// on the map's first row), w = z. An orthographic light's scales x and y by
// 2 / Fw, keeps w = 1 and maps z from n to f onto the clip depth `depth`
// describes.
Matrix4 light_clip(const LightParams& light, const LightClipDepth& depth, Target target);

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

// What an atlas or array variant's function takes at each call after the
// pixel (docs/function-form.md): its light's `light` and `sampling` members
// of ShadowParams and its tile or layer, which the engine's stage passes as
// constants of its own, as an engine passes a light of its own arrays.
struct CallLight {
  std::array<float, 4> light{};
  std::array<float, 4> sampling{};
  std::array<float, 4> map_tile{};  // map_layout atlas: the tile
  std::optional<int> map_layer;     // map_layout array: the layer, in the tile's place
};

// The fragment stage around `function_text` (the function form's file),
// declared as its `reflection` says, calling it with `call` where given.
// Output 0 is the light clip position it called penumbra_visibility() with
// and the visibility: (x, y, visibility, z_r), z_r its linear z as `depth`
// takes it out (w, perspective).
std::string engine_fragment_shader(Target target, const PassReflection& reflection,
                                   const std::string& function_text, const LightClipDepth& depth,
                                   const std::optional<CallLight>& call = std::nullopt);

}  // namespace penumbra
