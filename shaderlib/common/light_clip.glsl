// A receiver from its position in the light's clip space, as the function
// form and the deferred pass take it (docs/function-form.md).
#ifndef PENUMBRA_LIGHT_CLIP_GLSL
#define PENUMBRA_LIGHT_CLIP_GLSL

#include "common/map_encoding.glsl"

#if PENUMBRA_CLIP_Y_DOWN
// Direct3D's viewport puts clip-space y = +1 in a target's row 0.
#define PENUMBRA_CLIP_Y_TO_V (-0.5)
#else
#define PENUMBRA_CLIP_Y_TO_V 0.5
#endif

#if PENUMBRA_CLIP_Z_FROM_ZERO
// Direct3D's and Vulkan's projections map depth to clip z / w in [0, 1].
#define PENUMBRA_CLIP_Z_TO_DEPTH(z) (z)
#else
// OpenGL's map it to [-1, 1].
#define PENUMBRA_CLIP_Z_TO_DEPTH(z) (0.5 * (z) + 0.5)
#endif

// The receiver as the query pass reads it: (u, v) from the light's clip
// space, and its linear light-view z, which a perspective projection puts in
// w whatever range it maps z to; an orthographic one puts it in z alone.
vec3 clip_to_query(vec4 light_clip_position) {
  vec2 ndc = light_clip_position.xy / light_clip_position.w;
#if PENUMBRA_ORTHOGRAPHIC
  return vec3(0.5 + 0.5 * ndc.x, 0.5 + PENUMBRA_CLIP_Y_TO_V * ndc.y,
              shadow_linear(PENUMBRA_CLIP_Z_TO_DEPTH(light_clip_position.z / light_clip_position.w)));
#else
  return vec3(0.5 + 0.5 * ndc.x, 0.5 + PENUMBRA_CLIP_Y_TO_V * ndc.y, light_clip_position.w);
#endif
}

#endif
