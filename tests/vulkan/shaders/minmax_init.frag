#version 450
// Min-max level 1: (min, max) of the 2 x 2 map texels under this pixel, read
// at their centres through shadow_depth; a read past the map's last texel is
// clamped to it (clamp-to-edge), which leaves min and max unchanged.
#extension GL_GOOGLE_include_directive : require
#include "params.glsl"

layout(set = 0, binding = 1) uniform sampler2D shadow_depth;
layout(location = 0) out vec4 minmax;

void main() {
  vec2 step = params.source_size.zw;
  vec2 first = (2.0 * floor(gl_FragCoord.xy) + 0.5) * step;
  float a = textureLod(shadow_depth, first, 0.0).r;
  float b = textureLod(shadow_depth, first + vec2(step.x, 0.0), 0.0).r;
  float c = textureLod(shadow_depth, first + vec2(0.0, step.y), 0.0).r;
  float d = textureLod(shadow_depth, first + step, 0.0).r;
  minmax = vec4(min(min(a, b), min(c, d)), max(max(a, b), max(c, d)), 0.0, 0.0);
#ifdef SWAPPED
  // A wrong level 1, (max, min): a mip that differs from the CPU's.
  minmax = minmax.yxzw;
#endif
}
