#version 450

layout(binding = 0, std140) uniform ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
    vec4 source_size;
    vec4 minmax_info;
} params;

layout(location = 0) in float light_z;
layout(location = 0) out float depth_out;

void main()
{
    float stored = light_z * params.sampling.z;
    depth_out = stored;
    gl_FragDepth = stored;
}

