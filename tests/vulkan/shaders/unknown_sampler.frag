#version 450
// A query program declaring a sampler outside every reflection record:
// point.frag's resources, and "shadow_mapp" at binding 7.
#extension GL_GOOGLE_include_directive : require
#include "params.glsl"

layout(set = 0, binding = 1) uniform sampler2D shadow_depth;
layout(set = 0, binding = 3) uniform sampler2D receivers;
layout(set = 0, binding = 7) uniform sampler2D shadow_mapp;
layout(location = 0) out vec4 visibility;

void main() {
  vec2 uv = textureLod(receivers, gl_FragCoord.xy * params.screen_size.zw, 0.0).xy;
  visibility = textureLod(shadow_mapp, uv, 0.0) + textureLod(shadow_depth, uv, 0.0);
}
