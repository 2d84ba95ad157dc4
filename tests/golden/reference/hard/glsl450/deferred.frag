#version 450

layout(binding = 0, std140) uniform ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
    vec4 source_size;
    vec4 minmax_info;
    vec4 camera_inverse_0;
    vec4 camera_inverse_1;
    vec4 camera_inverse_2;
    vec4 camera_inverse_3;
    vec4 light_view_proj_0;
    vec4 light_view_proj_1;
    vec4 light_view_proj_2;
    vec4 light_view_proj_3;
    vec4 camera_depth_range;
} params;

layout(binding = 1) uniform sampler2D shadow_depth;
layout(binding = 10) uniform sampler2D camera_depth;

layout(location = 0) in vec2 screen_uv;
layout(location = 0) out vec4 visibility;
float penumbra_texel_reads;

vec3 clip_to_query(vec4 light_clip_position)
{
    vec2 ndc = light_clip_position.xy / vec2(light_clip_position.w);
    return vec3(0.5 + (0.5 * ndc.x), 0.5 + (0.5 * ndc.y), light_clip_position.w);
}

float shadow_reference(float z_receiver)
{
    return (z_receiver - params.sampling.y) * params.sampling.z;
}

float shadow_compare_point(vec2 uv, float z_receiver)
{
    penumbra_texel_reads += 1.0;
    float param = z_receiver;
    return float(shadow_reference(param) <= textureLod(shadow_depth, uv, 0.0).x);
}

float shadow_visibility(vec3 query)
{
    vec2 param = query.xy;
    float param_1 = query.z;
    float _83 = shadow_compare_point(param, param_1);
    return _83;
}

float receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _103 = shadow_visibility(param);
    return _103;
}

void main()
{
    penumbra_texel_reads = 0.0;
    float depth = textureLod(camera_depth, screen_uv, 0.0).x;
    vec4 clip = vec4((2.0 * screen_uv.x) - 1.0, (screen_uv.y - 0.5) / 0.5, (depth * params.camera_depth_range.x) + params.camera_depth_range.y, 1.0);
    mat4 camera_inverse = mat4(vec4(params.camera_inverse_0), vec4(params.camera_inverse_1), vec4(params.camera_inverse_2), vec4(params.camera_inverse_3));
    mat4 light_view_proj = mat4(vec4(params.light_view_proj_0), vec4(params.light_view_proj_1), vec4(params.light_view_proj_2), vec4(params.light_view_proj_3));
    vec4 world = camera_inverse * clip;
    vec4 param = light_view_proj * (world / vec4(world.w));
    vec3 query = clip_to_query(param);
    if (depth == params.camera_depth_range.z)
    {
        query = vec3(0.5, 0.5, 0.0);
    }
    vec3 param_1 = query;
    vec2 param_2 = floor(screen_uv * params.screen_size.xy);
    float _259 = receiver_visibility(param_1, param_2);
    float visible = _259;
    visibility = vec4(visible, penumbra_texel_reads, 0.0, 0.0);
}

