#version 300 es
precision highp float;
precision highp int;

layout(std140) uniform ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
    vec4 source_size;
    vec4 minmax_info;
} params;

uniform highp sampler2D shadow_depth;

in vec2 screen_uv;
layout(location = 0) out vec4 minmax;

vec2 minmax_source_uv(vec2 screen_uv_1)
{
    vec2 texel = floor(screen_uv_1 * params.screen_size.xy);
    return ((texel * 2.0) + vec2(0.5)) * params.source_size.zw;
}

void main()
{
    vec2 param = screen_uv;
    vec2 first = minmax_source_uv(param);
    vec2 _step = params.source_size.zw;
    float d00 = textureLod(shadow_depth, first, 0.0).x;
    float d10 = textureLod(shadow_depth, first + vec2(_step.x, 0.0), 0.0).x;
    float d01 = textureLod(shadow_depth, first + vec2(0.0, _step.y), 0.0).x;
    float d11 = textureLod(shadow_depth, first + _step, 0.0).x;
    minmax = vec4(min(min(d00, d10), min(d01, d11)), max(max(d00, d10), max(d01, d11)), 0.0, 0.0);
}

