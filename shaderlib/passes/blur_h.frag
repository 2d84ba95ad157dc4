#version 450
// screen_blur's blur_h pass ("Soft-Edged Shadows"), horizontal: taps along the row.
// Reads screen_factor .x (and, depth-aware, receivers .z) and writes
// vec4(blurred, 0, 0, 0).
#extension GL_GOOGLE_include_directive : require
#include "variant.glsl"
#include "common/blur.glsl"

layout(location = 0) in vec2 screen_uv;  // this pixel's centre in [0, 1]
layout(location = 0) out vec4 blurred;

void main() {
  blurred = vec4(blur_factor(screen_uv, vec2(1.0, 0.0)), 0.0, 0.0, 0.0);
}
