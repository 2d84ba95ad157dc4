#version 450
// screen_blur's composite pass ("Soft-Edged Shadows"), shared by every screen_blur
// variant: the scene colour darkened by the blurred factor, alpha kept.
#extension GL_GOOGLE_include_directive : require
#include "variant.glsl"

layout(set = 0, binding = PENUMBRA_SLOT_SCREEN_FACTOR) uniform sampler2D screen_factor;  // blur_v's output
layout(set = 0, binding = PENUMBRA_SLOT_SCENE_COLOUR) uniform sampler2D scene_colour;   // RGBA

layout(location = 0) in vec2 screen_uv;  // this pixel's centre in [0, 1]
layout(location = 0) out vec4 colour;

void main() {
  vec4 scene = textureLod(scene_colour, screen_uv, 0.0);
  float factor = textureLod(screen_factor, screen_uv, 0.0).x;
  colour = vec4(scene.rgb * factor, scene.a);
}
