#version 450
// Query pass without a comparison sampler (the Direct3D 9 style): returns the
// stored normalized depth nearest to the receiver's (u, v).
#extension GL_GOOGLE_include_directive : require
#include "params.glsl"

layout(set = 0, binding = 1) uniform sampler2D shadow_depth;
layout(set = 0, binding = 3) uniform sampler2D receivers;
layout(location = 0) out vec4 visibility;

void main() {
  vec2 uv = textureLod(receivers, gl_FragCoord.xy * params.screen_size.zw, 0.0).xy;
  visibility = vec4(textureLod(shadow_depth, uv, 0.0).r);
}
