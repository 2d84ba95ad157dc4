#version 450
// The function form: penumbra_visibility(), which an engine's own surface or
// deferred shader calls with a fragment's light clip-space position. The
// compiler keeps that function and everything it reads, prefixes every name
// with penumbra_, and drops the test harness below it (docs/function-form.md).
#extension GL_GOOGLE_include_directive : require
#include "variant.glsl"
#include "techniques/technique.glsl"
#include "common/light_clip.glsl"

// Visibility of the light in [0, 1] at a receiver whose position the light's
// view-projection matrix takes to `light_clip_position`. With the rotation
// key, `pixel` is the fragment's integer column and row (floor of its
// window position), which turns the samples. With receiver_plane, call it in
// uniform control flow: it takes screen derivatives. With map_layout atlas
// or array, each call names its light: ShadowParams' `light` and `sampling`
// members for it, and its tile in the atlas (`map_tile`) or its layer of the
// array (`map_layer`).
#if PENUMBRA_ROTATION_IGN
#define PENUMBRA_PIXEL_PARAMETER , vec2 pixel
#define PENUMBRA_HARNESS_PIXEL , floor(gl_FragCoord.xy)
#else
#define PENUMBRA_PIXEL_PARAMETER
#define PENUMBRA_HARNESS_PIXEL
#endif
#if PENUMBRA_MAP_ATLAS
#define PENUMBRA_LIGHT_PARAMETERS , vec4 light, vec4 sampling, vec4 map_tile
#define PENUMBRA_HARNESS_LIGHT , harness_light, harness_sampling, harness_map_tile
#elif PENUMBRA_MAP_ARRAY
#define PENUMBRA_LIGHT_PARAMETERS , vec4 light, vec4 sampling, int map_layer
#define PENUMBRA_HARNESS_LIGHT , harness_light, harness_sampling, harness_map_layer
#else
#define PENUMBRA_LIGHT_PARAMETERS
#define PENUMBRA_HARNESS_LIGHT
#endif

float penumbra_visibility(vec4 light_clip_position PENUMBRA_PIXEL_PARAMETER
                              PENUMBRA_LIGHT_PARAMETERS) {
#if !PENUMBRA_ROTATION_IGN
  vec2 pixel = vec2(0.0);
#endif
  penumbra_texel_reads = 0.0;
#if PENUMBRA_MAP_ATLAS
  set_call(light, sampling, map_tile);
#elif PENUMBRA_MAP_ARRAY
  set_call(light, sampling, map_layer);
#endif
  vec3 query = clip_to_query(light_clip_position);
#if PENUMBRA_RECEIVER_PLANE
  penumbra_depth_slope = receiver_depth_slope(dFdx(query), dFdy(query), query.z);
#endif
  return receiver_visibility(query, pixel);
}

// The harness that gives the SPIR-V module an entry point; the function form
// leaves it out.
layout(location = 0) in vec4 harness_clip_position;
layout(location = 0) out vec4 harness_visibility;
#if PENUMBRA_MAP_ATLAS || PENUMBRA_MAP_ARRAY
// The light each call names, as an engine's own uniforms would give it: not
// from ShadowParams, so that the reflection lists the block only where the
// function itself reads it.
layout(location = 1) in vec4 harness_light;
layout(location = 2) in vec4 harness_sampling;
#if PENUMBRA_MAP_ATLAS
layout(location = 3) in vec4 harness_map_tile;
#else
layout(location = 3) flat in int harness_map_layer;
#endif
#endif

void main() {
  float visible = penumbra_visibility(harness_clip_position PENUMBRA_HARNESS_PIXEL
                                          PENUMBRA_HARNESS_LIGHT);
  harness_visibility = vec4(visible, penumbra_texel_reads, 0.0, 0.0);
}
