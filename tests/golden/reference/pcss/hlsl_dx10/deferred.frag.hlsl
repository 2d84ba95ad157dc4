static const float2 POISSON_DISK[16] = { float2(-0.94201624393463134765625f, -0.39906215667724609375f), float2(0.94558608531951904296875f, -0.768907248973846435546875f), float2(-0.094184100627899169921875f, -0.929388701915740966796875f), float2(0.34495937824249267578125f, 0.29387760162353515625f), float2(-0.91588580608367919921875f, 0.4577143192291259765625f), float2(-0.8154423236846923828125f, -0.87912464141845703125f), float2(-0.38277542591094970703125f, 0.2767684459686279296875f), float2(0.9748439788818359375f, 0.7564837932586669921875f), float2(0.4432332515716552734375f, -0.9751155376434326171875f), float2(0.5374298095703125f, -0.473734200000762939453125f), float2(-0.2649691104888916015625f, -0.418930232524871826171875f), float2(0.79197514057159423828125f, 0.19090187549591064453125f), float2(-0.24188840389251708984375f, 0.997065067291259765625f), float2(-0.8140995502471923828125f, 0.91437590122222900390625f), float2(0.1998412609100341796875f, 0.786413669586181640625f), float2(0.14383161067962646484375f, -0.141007900238037109375f) };

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
Texture2D<float> shadow_cmp : register(t2);
SamplerComparisonState _shadow_cmp_sampler : register(s2);
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

float shadow_depth_point(float2 uv)
{
    penumbra_texel_reads += 1.0f;
    return shadow_depth.SampleLevel(_shadow_depth_sampler, uv, 0.0f).x * params_sampling.w;
}

void FindBlocker(inout float avgBlockerDepth, inout float numBlockers, float2 uv, float zReceiver)
{
    float searchWidth = (params_light.w * (zReceiver - params_light.z)) / zReceiver;
    float blockerSum = 0.0f;
    numBlockers = 0.0f;
    [loop]
    for (int i = 0; i < 16; i++)
    {
        float2 offset = POISSON_DISK[i] * searchWidth;
        float2 param = uv + offset;
        float _248 = shadow_depth_point(param);
        float shadowMapDepth = _248;
        bool blocks = shadowMapDepth < (zReceiver - params_sampling.y);
        blockerSum += (blocks ? shadowMapDepth : 0.0f);
        numBlockers += float(blocks);
    }
    float _270;
    if (numBlockers > 0.0f)
    {
        _270 = blockerSum / numBlockers;
    }
    else
    {
        _270 = zReceiver;
    }
    avgBlockerDepth = _270;
}

float PenumbraSize(float zReceiver, float zBlocker)
{
    return (zReceiver - zBlocker) / zBlocker;
}

float shadow_reference(float z_receiver)
{
    return (z_receiver - params_sampling.y) * params_sampling.z;
}

float shadow_compare_bilinear(float2 uv, float z_receiver)
{
    penumbra_texel_reads += 4.0f;
    float param = z_receiver;
    float reference = shadow_reference(param);
    float3 _116 = float3(uv, reference);
    return shadow_cmp.SampleCmpLevelZero(_shadow_cmp_sampler, _116.xy, _116.z);
}

float PCF_Filter(float2 uv, float zReceiver, float filterRadiusUV)
{
    float sum = 0.0f;
    [loop]
    for (int i = 0; i < 16; i++)
    {
        float2 offset = POISSON_DISK[i] * filterRadiusUV;
        float2 param = uv + offset;
        float param_1 = zReceiver;
        float _206 = shadow_compare_bilinear(param, param_1);
        sum += _206;
    }
    return sum / 16.0f;
}

float PCSS(float3 coords)
{
    float2 uv = coords.xy;
    float zReceiver = coords.z;
    if (!(zReceiver > params_light.z))
    {
        return 1.0f;
    }
    float avgBlockerDepth = 0.0f;
    float numBlockers = 0.0f;
    float2 param_2 = uv;
    float param_3 = zReceiver;
    float param;
    float param_1;
    FindBlocker(param, param_1, param_2, param_3);
    avgBlockerDepth = param;
    numBlockers = param_1;
    if (numBlockers < 1.0f)
    {
        return 1.0f;
    }
    float param_4 = zReceiver;
    float param_5 = max(avgBlockerDepth, params_light.z);
    float penumbraRatio = PenumbraSize(param_4, param_5);
    float filterRadiusUV = ((penumbraRatio * params_light.w) * params_light.z) / coords.z;
    float2 param_6 = uv;
    float param_7 = zReceiver;
    float param_8 = filterRadiusUV;
    float _335 = PCF_Filter(param_6, param_7, param_8);
    return _335;
}

float shadow_visibility(float3 query)
{
    float3 param = query;
    float _340 = PCSS(param);
    return _340;
}

float receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _360 = shadow_visibility(param);
    return _360;
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
    float _516 = receiver_visibility(param_1, param_2);
    float visible = _516;
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
