cbuffer ShadowParams : register(b0)
{
    float4 params_shadow_map_size : packoffset(c0);
    float4 params_light : packoffset(c1);
    float4 params_sampling : packoffset(c2);
    float4 params_screen_size : packoffset(c3);
    float4 params_source_size : packoffset(c4);
    float4 params_minmax_info : packoffset(c5);
    float4 params_camera_inverse_0 : packoffset(c6);
    float4 params_camera_inverse_1 : packoffset(c7);
    float4 params_camera_inverse_2 : packoffset(c8);
    float4 params_camera_inverse_3 : packoffset(c9);
    float4 params_light_view_proj_0 : packoffset(c10);
    float4 params_light_view_proj_1 : packoffset(c11);
    float4 params_light_view_proj_2 : packoffset(c12);
    float4 params_light_view_proj_3 : packoffset(c13);
    float4 params_camera_depth_range : packoffset(c14);
};

Texture2D<float4> shadow_depth : register(t1);
SamplerState _shadow_depth_sampler : register(s1);
Texture2D<float4> camera_depth : register(t10);
SamplerState _camera_depth_sampler : register(s10);

static float2 screen_uv;
static float4 visibility;

struct SPIRV_Cross_Input
{
    float2 screen_uv : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float4 visibility : SV_Target0;
};

static float penumbra_texel_reads;

float3 clip_to_query(float4 light_clip_position)
{
    float2 ndc = light_clip_position.xy / light_clip_position.w.xx;
    return float3(0.5f + (0.5f * ndc.x), 0.5f + ((-0.5f) * ndc.y), light_clip_position.w);
}

float shadow_reference(float z_receiver)
{
    return (z_receiver - params_sampling.y) * params_sampling.z;
}

float shadow_compare_point(float2 uv, float z_receiver)
{
    penumbra_texel_reads += 1.0f;
    float param = z_receiver;
    return float(shadow_reference(param) <= shadow_depth.SampleLevel(_shadow_depth_sampler, uv, 0.0f).x);
}

float shadow_visibility(float3 query)
{
    float2 param = query.xy;
    float param_1 = query.z;
    float _83 = shadow_compare_point(param, param_1);
    return _83;
}

float receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _103 = shadow_visibility(param);
    return _103;
}

void frag_main()
{
    penumbra_texel_reads = 0.0f;
    float depth = camera_depth.SampleLevel(_camera_depth_sampler, screen_uv, 0.0f).x;
    float4 clip = float4((2.0f * screen_uv.x) - 1.0f, (screen_uv.y - 0.5f) / (-0.5f), (depth * params_camera_depth_range.x) + params_camera_depth_range.y, 1.0f);
    float4x4 camera_inverse = float4x4(float4(params_camera_inverse_0), float4(params_camera_inverse_1), float4(params_camera_inverse_2), float4(params_camera_inverse_3));
    float4x4 light_view_proj = float4x4(float4(params_light_view_proj_0), float4(params_light_view_proj_1), float4(params_light_view_proj_2), float4(params_light_view_proj_3));
    float4 world = mul(clip, camera_inverse);
    float4 param = mul(world / world.w.xxxx, light_view_proj);
    float3 query = clip_to_query(param);
    if (depth == params_camera_depth_range.z)
    {
        query = float3(0.5f, 0.5f, 0.0f);
    }
    float3 param_1 = query;
    float2 param_2 = floor(screen_uv * params_screen_size.xy);
    float _260 = receiver_visibility(param_1, param_2);
    float visible = _260;
    visibility = float4(visible, penumbra_texel_reads, 0.0f, 0.0f);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    screen_uv = stage_input.screen_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.visibility = visibility;
    return stage_output;
}
