#version 450
// Min-max level l from level l - 1 (minmax_source): min of the 2 x 2 minima,
// max of the maxima, clamped to the source's edge like minmax_init.frag.
#extension GL_GOOGLE_include_directive : require
#include "params.glsl"

layout(set = 0, binding = 5) uniform sampler2D minmax_source;
layout(location = 0) out vec4 minmax;

void main() {
  vec2 step = params.source_size.zw;
  vec2 first = (2.0 * floor(gl_FragCoord.xy) + 0.5) * step;
  vec2 a = textureLod(minmax_source, first, 0.0).rg;
  vec2 b = textureLod(minmax_source, first + vec2(step.x, 0.0), 0.0).rg;
  vec2 c = textureLod(minmax_source, first + vec2(0.0, step.y), 0.0).rg;
  vec2 d = textureLod(minmax_source, first + step, 0.0).rg;
  minmax = vec4(min(min(a.x, b.x), min(c.x, d.x)), max(max(a.y, b.y), max(c.y, d.y)), 0.0, 0.0);
}
