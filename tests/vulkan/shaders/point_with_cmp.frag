#version 450
// point.frag with shadow_cmp declared too, so shadow_depth binds the depth
// image. The comparison term is multiplied by zero: the output stays exact.
#extension GL_GOOGLE_include_directive : require
#include "params.glsl"

layout(set = 0, binding = 1) uniform sampler2D shadow_depth;
layout(set = 0, binding = 2) uniform sampler2DShadow shadow_cmp;
layout(set = 0, binding = 3) uniform sampler2D receivers;
layout(location = 0) out vec4 visibility;

void main() {
  vec2 uv = textureLod(receivers, gl_FragCoord.xy * params.screen_size.zw, 0.0).xy;
  float unused = textureLod(shadow_cmp, vec3(uv, 0.0), 0.0);
  visibility = vec4(textureLod(shadow_depth, uv, 0.0).r + 0.0 * unused);
}
