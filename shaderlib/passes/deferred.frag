#version 450
// Deferred mask pass: the query's visibility and texel reads at the receiver
// each pixel of an engine's camera depth buffer holds, rebuilt with the
// inverse of the camera's view-projection and taken to the map with the
// light's (docs/deferred-mask.md).
#extension GL_GOOGLE_include_directive : require
#define PENUMBRA_DEFERRED_PARAMS 1
#include "variant.glsl"
#include "techniques/technique.glsl"
#include "common/light_clip.glsl"

layout(set = 0, binding = PENUMBRA_SLOT_CAMERA_DEPTH) uniform sampler2D camera_depth;

layout(location = 0) in vec2 screen_uv;  // this pixel's centre in [0, 1]
layout(location = 0) out vec4 visibility;

void main() {
  penumbra_texel_reads = 0.0;
  PENUMBRA_CALL_FROM_PARAMS();
  float depth = textureLod(camera_depth, screen_uv, 0.0).x;
  // The camera's clip space at this pixel: its rows run as the light's map's
  // do on this API (PENUMBRA_CLIP_Y_TO_V), its z as the engine maps depth.
  vec4 clip = vec4(2.0 * screen_uv.x - 1.0, (screen_uv.y - 0.5) / PENUMBRA_CLIP_Y_TO_V,
                   depth * params.camera_depth_range.x + params.camera_depth_range.y, 1.0);
  mat4 camera_inverse = mat4(params.camera_inverse_0, params.camera_inverse_1,
                             params.camera_inverse_2, params.camera_inverse_3);
  mat4 light_view_proj = mat4(params.light_view_proj_0, params.light_view_proj_1,
                              params.light_view_proj_2, params.light_view_proj_3);
  vec4 world = camera_inverse * clip;
  vec3 query = clip_to_query(light_view_proj * (world / world.w));
  // Where the buffer holds its clear, no surface: a receiver at the light,
  // which is lit. Selected, not branched on, so that receiver_plane's
  // derivatives are taken in uniform control flow.
  if (depth == params.camera_depth_range.z) query = vec3(0.5, 0.5, 0.0);
#if PENUMBRA_RECEIVER_PLANE
  penumbra_depth_slope = receiver_depth_slope(dFdx(query), dFdy(query), query.z);
#endif
  float visible = receiver_visibility(query, floor(screen_uv * params.screen_size.xy));
  visibility = vec4(visible, penumbra_texel_reads, 0.0, 0.0);
}
