// screen_blur's separable Gaussian (after the GameDev.net article "Soft-Edged
// Shadows"), shared by blur_h and blur_v.
// BLUR_RADIUS R, BLUR_WEIGHTS[2R + 1] (taps -R..R), PENUMBRA_DEPTH_AWARE and
// BLUR_DEPTH_TOLERANCE come from variant.glsl. Taps sit at pixel centres of
// the screen-sized input; a tap past the screen's edge reads the edge pixel
// (the sampler's clamp-to-edge addressing).
#ifndef PENUMBRA_BLUR_GLSL
#define PENUMBRA_BLUR_GLSL

#include "common/params.glsl"

// blur_h: the query pass's factor (.x); blur_v: blur_h's output (.x).
layout(set = 0, binding = PENUMBRA_SLOT_SCREEN_FACTOR) uniform sampler2D screen_factor;
#if PENUMBRA_DEPTH_AWARE
layout(set = 0, binding = PENUMBRA_SLOT_RECEIVERS) uniform sampler2D receivers;  // the screen's (u, v, z_r)
#endif

// The blurred factor at the pixel whose centre is `screen_uv`, along `axis`
// ((1, 0): rows, blur_h; (0, 1): columns, blur_v). Depth-aware variants give
// weight 0 to taps whose receiver z differs from the centre's by more than
// BLUR_DEPTH_TOLERANCE * |z_centre| and divide by the weights kept (the
// centre is always kept); the others sum the baked weights as they are.
float blur_factor(vec2 screen_uv, vec2 axis) {
  vec2 pixel = floor(screen_uv * params.screen_size.xy);
  float sum = 0.0;
#if PENUMBRA_DEPTH_AWARE
  float z_centre = textureLod(receivers, (pixel + 0.5) * params.screen_size.zw, 0.0).z;
  float limit = BLUR_DEPTH_TOLERANCE * abs(z_centre);
  float kept = 0.0;
#endif
  for (int k = -BLUR_RADIUS; k <= BLUR_RADIUS; ++k) {
    vec2 uv = (pixel + axis * float(k) + 0.5) * params.screen_size.zw;
    float weight = BLUR_WEIGHTS[k + BLUR_RADIUS];
#if PENUMBRA_DEPTH_AWARE
    float z = textureLod(receivers, uv, 0.0).z;
    weight = abs(z - z_centre) > limit ? 0.0 : weight;
    kept += weight;
#endif
    sum += weight * textureLod(screen_factor, uv, 0.0).x;
  }
#if PENUMBRA_DEPTH_AWARE
  return sum / kept;
#else
  return sum;
#endif
}

#endif
