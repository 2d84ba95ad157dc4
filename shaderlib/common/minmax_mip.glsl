// The min-max mip (Dmitriev 2007) and its reads, for the techniques that use it
// (minmax_pcf, backprojection, pcss_minmax): a square chain of 2^(N-1)
// texels a side whose mip m holds hierarchy level m + 1, (min, max) of
// normalized linear depth (shadow_normalized()), at texel (0, 0); level 0
// is the map itself, read through shadow_texel().
#ifndef PENUMBRA_MINMAX_MIP_GLSL
#define PENUMBRA_MINMAX_MIP_GLSL

#include "common/shadow_map.glsl"

layout(set = 0, binding = PENUMBRA_SLOT_SHADOW_MINMAX) uniform sampler2D shadow_minmax;

// (min, max) normalized depth of hierarchy node `node` at `level`: level 0
// reads the map, level l its W_l x H_l texels (W_l = ceil(W / 2^l)) at the
// start of the square 2^(N-l) mip l - 1, whose texel centres are
// (node + 0.5) 2^(l-N) for every map size.
vec2 minmax_node(float level, vec2 node) {
  if (level < 0.5) {
    float depth = shadow_texel(node);
    return vec2(depth, depth);
  }
  penumbra_texel_reads += 1.0;
  vec2 uv = (node + 0.5) * exp2(level - MINMAX_TOP_LEVEL);
  return textureLod(shadow_minmax, uv, level - 1.0).rg;
}

// (min, max) of the whole map: the top node, level N (1x1).
vec2 minmax_top_node() {
  penumbra_texel_reads += 1.0;
  return textureLod(shadow_minmax, vec2(0.5), MINMAX_TOP_LEVEL - 1.0).rg;
}

#endif
