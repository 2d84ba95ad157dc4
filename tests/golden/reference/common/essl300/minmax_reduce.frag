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

uniform highp sampler2D minmax_source;

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
    vec2 r00 = textureLod(minmax_source, first, 0.0).xy;
    vec2 r10 = textureLod(minmax_source, first + vec2(_step.x, 0.0), 0.0).xy;
    vec2 r01 = textureLod(minmax_source, first + vec2(0.0, _step.y), 0.0).xy;
    vec2 r11 = textureLod(minmax_source, first + _step, 0.0).xy;
    minmax = vec4(min(min(r00.x, r10.x), min(r01.x, r11.x)), max(max(r00.y, r10.y), max(r01.y, r11.y)), 0.0, 0.0);
}

