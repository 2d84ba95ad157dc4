#version 450
// Min-max mip, level l + 1 from level l (Dmitriev 2007): min of the 2x2 minima
// and max of the maxima under this texel. The target is ceil(Ws/2) x
// ceil(Hs/2); a read past the source's last texel is clamped to it, which
// leaves min and max unchanged.
#extension GL_GOOGLE_include_directive : require
#include "variant.glsl"
#include "common/minmax_reduce.glsl"

layout(set = 0, binding = PENUMBRA_SLOT_MINMAX_SOURCE) uniform sampler2D minmax_source;  // level l, (min, max)

layout(location = 0) in vec2 screen_uv;
layout(location = 0) out vec4 minmax;

void main() {
  vec2 first = minmax_source_uv(screen_uv);
  vec2 step = params.source_size.zw;
  vec2 r00 = textureLod(minmax_source, first, 0.0).rg;
  vec2 r10 = textureLod(minmax_source, first + vec2(step.x, 0.0), 0.0).rg;
  vec2 r01 = textureLod(minmax_source, first + vec2(0.0, step.y), 0.0).rg;
  vec2 r11 = textureLod(minmax_source, first + step, 0.0).rg;
  minmax = vec4(min(min(r00.x, r10.x), min(r01.x, r11.x)),
                max(max(r00.y, r10.y), max(r01.y, r11.y)), 0.0, 0.0);
}
