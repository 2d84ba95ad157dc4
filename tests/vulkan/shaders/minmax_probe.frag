#version 450
// Query pass reading the min-max mip: each receiver is (u, v, lod); the
// output is that texel's (min, max) as (.x, .y), so the runtime's visibility
// is the min and its texel reads the max.
#extension GL_GOOGLE_include_directive : require
#include "params.glsl"

// Declared, unread: the query passes reading the mip declare the map too.
layout(set = 0, binding = 1) uniform sampler2D shadow_depth;
layout(set = 0, binding = 3) uniform sampler2D receivers;
layout(set = 0, binding = 4) uniform sampler2D shadow_minmax;
layout(location = 0) out vec4 visibility;

void main() {
  vec3 query = textureLod(receivers, gl_FragCoord.xy * params.screen_size.zw, 0.0).xyz;
  visibility = vec4(textureLod(shadow_minmax, query.xy, query.z).rg, 0.0, 0.0);
}
