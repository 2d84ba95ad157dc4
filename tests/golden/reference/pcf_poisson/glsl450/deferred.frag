#version 450

const vec2 PCF_DISK[16] = vec2[](vec2(-0.94201624393463134765625, -0.39906215667724609375), vec2(0.94558608531951904296875, -0.768907248973846435546875), vec2(-0.094184100627899169921875, -0.929388701915740966796875), vec2(0.34495937824249267578125, 0.29387760162353515625), vec2(-0.91588580608367919921875, 0.4577143192291259765625), vec2(-0.8154423236846923828125, -0.87912464141845703125), vec2(-0.38277542591094970703125, 0.2767684459686279296875), vec2(0.9748439788818359375, 0.7564837932586669921875), vec2(0.4432332515716552734375, -0.9751155376434326171875), vec2(0.5374298095703125, -0.473734200000762939453125), vec2(-0.2649691104888916015625, -0.418930232524871826171875), vec2(0.79197514057159423828125, 0.19090187549591064453125), vec2(-0.24188840389251708984375, 0.997065067291259765625), vec2(-0.8140995502471923828125, 0.91437590122222900390625), vec2(0.1998412609100341796875, 0.786413669586181640625), vec2(0.14383161067962646484375, -0.141007900238037109375));

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

layout(binding = 2) uniform sampler2DShadow shadow_cmp;
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

float shadow_compare_bilinear(vec2 uv, float z_receiver)
{
    penumbra_texel_reads += 4.0;
    float param = z_receiver;
    float reference = shadow_reference(param);
    vec3 _72 = vec3(uv, reference);
    return textureLod(shadow_cmp, vec3(_72.xy, _72.z), 0.0);
}

float shadow_visibility(vec3 query)
{
    float sum = 0.0;
    for (int i = 0; i < 16; i++)
    {
        vec2 offset = PCF_DISK[i] * params.sampling.x;
        vec2 param = query.xy + offset;
        float param_1 = query.z;
        float _160 = shadow_compare_bilinear(param, param_1);
        sum += _160;
    }
    return sum / 16.0;
}

float receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _189 = shadow_visibility(param);
    return _189;
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
    float _348 = receiver_visibility(param_1, param_2);
    float visible = _348;
    visibility = vec4(visible, penumbra_texel_reads, 0.0, 0.0);
}

