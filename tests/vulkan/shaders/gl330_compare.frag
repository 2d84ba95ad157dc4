#version 330
// compare.frag in the shape of the emitted glsl330 query.frag: loose
// samplers without bindings and params read through the struct.
#extension GL_GOOGLE_include_directive : require
#include "gl330_params.glsl"

uniform sampler2D shadow_depth;
uniform sampler2DShadow shadow_cmp;
uniform sampler2D receivers;

in vec2 screen_uv;
layout(location = 0) out vec4 visibility;

void main()
{
    vec3 query = textureLod(receivers, screen_uv, 0.0).xyz;
    float reference = (query.z - params.sampling.y) * params.sampling.z;
    float unused = textureLod(shadow_depth, query.xy, 0.0).x;
    visibility = vec4(texture(shadow_cmp, vec3(query.xy, reference)) + 0.0 * unused);
}
