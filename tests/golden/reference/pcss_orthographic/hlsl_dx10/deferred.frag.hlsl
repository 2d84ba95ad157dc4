static const float2 POISSON_DISK[16] = { float2(-0.3564817905426025390625f, -0.7736518383026123046875f), float2(0.7706091403961181640625f, -0.476450383663177490234375f), float2(0.040970109403133392333984375f, -0.96095740795135498046875f), float2(0.013376322574913501739501953125f, 0.997840583324432373046875f), float2(0.591416180133819580078125f, -0.011377436108887195587158203125f), float2(0.1291187703609466552734375f, -0.02888503484427928924560546875f), float2(0.3763323128223419189453125f, 0.4415138661861419677734375f), float2(0.549356281757354736328125f, 0.793806552886962890625f), float2(-0.011186738498508930206298828125f, 0.4573924839496612548828125f), float2(0.784348905086517333984375f, 0.3635326325893402099609375f), float2(-0.797832071781158447265625f, -0.535640716552734375f), float2(0.480243146419525146484375f, -0.69643151760101318359375f), float2(-0.750289142131805419921875f, 0.620359599590301513671875f), float2(-0.95311391353607177734375f, -0.03544120490550994873046875f), float2(-0.4556185305118560791015625f, -0.09509353339672088623046875f), float2(0.12933044135570526123046875f, -0.57352435588836669921875f) };

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

float shadow_linear(float stored)
{
    return ((1.0f - stored) * params_light.z) + (stored * params_sampling.w);
}

float3 clip_to_query(float4 light_clip_position)
{
    float2 ndc = light_clip_position.xy / light_clip_position.w.xx;
    float param = light_clip_position.z / light_clip_position.w;
    return float3(0.5f + (0.5f * ndc.x), 0.5f + ((-0.5f) * ndc.y), shadow_linear(param));
}

float shadow_depth_point(float2 uv)
{
    penumbra_texel_reads += 1.0f;
    float param = shadow_depth.SampleLevel(_shadow_depth_sampler, uv, 0.0f).x;
    return shadow_linear(param);
}

void FindBlocker(inout float avgBlockerDepth, inout float numBlockers, float2 uv, float zReceiver)
{
    float searchWidth = params_light.w * (zReceiver - params_light.z);
    float blockerSum = 0.0f;
    numBlockers = 0.0f;
    [loop]
    for (int i = 0; i < 16; i++)
    {
        float2 offset = POISSON_DISK[i] * searchWidth;
        float2 param = uv + offset;
        float _262 = shadow_depth_point(param);
        float shadowMapDepth = _262;
        bool blocks = shadowMapDepth < (zReceiver - params_sampling.y);
        blockerSum += (blocks ? shadowMapDepth : 0.0f);
        numBlockers += float(blocks);
    }
    float _284;
    if (numBlockers > 0.0f)
    {
        _284 = blockerSum / numBlockers;
    }
    else
    {
        _284 = zReceiver;
    }
    avgBlockerDepth = _284;
}

float shadow_encode(float z)
{
    return (z - params_light.z) / (params_sampling.w - params_light.z);
}

float shadow_reference(float z_receiver)
{
    float param = z_receiver - params_sampling.y;
    return shadow_encode(param);
}

float shadow_compare_bilinear(float2 uv, float z_receiver)
{
    penumbra_texel_reads += 4.0f;
    float param = z_receiver;
    float reference = shadow_reference(param);
    float3 _140 = float3(uv, reference);
    return shadow_cmp.SampleCmpLevelZero(_shadow_cmp_sampler, _140.xy, _140.z);
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
        float _223 = shadow_compare_bilinear(param, param_1);
        sum += _223;
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
    float filterRadiusUV = params_light.w * (zReceiver - max(avgBlockerDepth, params_light.z));
    float2 param_4 = uv;
    float param_5 = zReceiver;
    float param_6 = filterRadiusUV;
    float _339 = PCF_Filter(param_4, param_5, param_6);
    return _339;
}

float shadow_visibility(float3 query)
{
    float3 param = query;
    float _344 = PCSS(param);
    return _344;
}

float receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _364 = shadow_visibility(param);
    return _364;
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
    float _525 = receiver_visibility(param_1, param_2);
    float visible = _525;
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
