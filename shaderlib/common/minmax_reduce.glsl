// What both min-max build passes share: the source texel they start from.
#ifndef PENUMBRA_MINMAX_REDUCE_GLSL
#define PENUMBRA_MINMAX_REDUCE_GLSL

#include "common/shadow_map.glsl"

// Centre of source texel 2i, i = floor(screen_uv * target size) this pass's
// texel; the others of the 2x2 are one source texel (source_size.zw) away.
vec2 minmax_source_uv(vec2 screen_uv) {
  vec2 texel = floor(screen_uv * params.screen_size.xy);
  return (2.0 * texel + 0.5) * params.source_size.zw;
}

#endif
