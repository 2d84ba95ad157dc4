#version 330

struct ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
    vec4 source_size;
    vec4 minmax_info;
};

uniform ShadowParams params;

layout(location = 0) in vec3 position;
out float light_z;

void main()
{
    float far_plane = params.sampling.w;
    float xy_scale = (2.0 * params.light.z) / params.light.y;
    float clip_z = ((position.z - params.light.z) * far_plane) / (far_plane - params.light.z);
    gl_Position = vec4(position.xy * xy_scale, clip_z, position.z);
    light_z = position.z;
    gl_Position.z = 2.0 * gl_Position.z - gl_Position.w;
}

