#version 450
// Min-max mip, level 1 (Dmitriev 2007): (min, max) of the 2x2 map texels under
// this texel, in normalized linear depth (an engine's map decoded:
// shadow_normalized(), common/map_encoding.glsl). The target is
// ceil(W/2) x ceil(H/2); a read past the map's last texel is clamped to it,
// which leaves min and max unchanged.
#extension GL_GOOGLE_include_directive : require
#include "variant.glsl"
#include "common/minmax_reduce.glsl"

layout(location = 0) in vec2 screen_uv;
layout(location = 0) out vec4 minmax;

void main() {
  vec2 first = minmax_source_uv(screen_uv);
  vec2 step = params.source_size.zw;
  float d00 = shadow_normalized(textureLod(shadow_depth, first, 0.0).r);
  float d10 = shadow_normalized(textureLod(shadow_depth, first + vec2(step.x, 0.0), 0.0).r);
  float d01 = shadow_normalized(textureLod(shadow_depth, first + vec2(0.0, step.y), 0.0).r);
  float d11 = shadow_normalized(textureLod(shadow_depth, first + step, 0.0).r);
  minmax = vec4(min(min(d00, d10), min(d01, d11)), max(max(d00, d10), max(d01, d11)), 0.0, 0.0);
}
