#version 450
// Query pass: one bilinear comparison at the receiver's (u, v) with its z_r,
// biased and normalized as the map is.
#extension GL_GOOGLE_include_directive : require
#include "params.glsl"

layout(set = 0, binding = 1) uniform sampler2D shadow_depth;
layout(set = 0, binding = 2) uniform sampler2DShadow shadow_cmp;
layout(set = 0, binding = 3) uniform sampler2D receivers;
layout(location = 0) out vec4 visibility;

void main() {
  vec3 query = textureLod(receivers, gl_FragCoord.xy * params.screen_size.zw, 0.0).xyz;
  float reference = (query.z - params.sampling.y) * params.sampling.z;
  visibility = vec4(textureLod(shadow_cmp, vec3(query.xy, reference), 0.0));
}
