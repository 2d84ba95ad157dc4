static const float2 POISSON_DISK[16] = { float2(-0.3564817905426025390625f, -0.7736518383026123046875f), float2(0.7706091403961181640625f, -0.476450383663177490234375f), float2(0.040970109403133392333984375f, -0.96095740795135498046875f), float2(0.013376322574913501739501953125f, 0.997840583324432373046875f), float2(0.591416180133819580078125f, -0.011377436108887195587158203125f), float2(0.1291187703609466552734375f, -0.02888503484427928924560546875f), float2(0.3763323128223419189453125f, 0.4415138661861419677734375f), float2(0.549356281757354736328125f, 0.793806552886962890625f), float2(-0.011186738498508930206298828125f, 0.4573924839496612548828125f), float2(0.784348905086517333984375f, 0.3635326325893402099609375f), float2(-0.797832071781158447265625f, -0.535640716552734375f), float2(0.480243146419525146484375f, -0.69643151760101318359375f), float2(-0.750289142131805419921875f, 0.620359599590301513671875f), float2(-0.95311391353607177734375f, -0.03544120490550994873046875f), float2(-0.4556185305118560791015625f, -0.09509353339672088623046875f), float2(0.12933044135570526123046875f, -0.57352435588836669921875f) };

cbuffer ShadowParams : register(b0)
{
    float4 params_shadow_map_size : packoffset(c0);
    float4 params_light : packoffset(c1);
    float4 params_sampling : packoffset(c2);
    float4 params_screen_size : packoffset(c3);
    float4 params_source_size : packoffset(c4);
    float4 params_minmax_info : packoffset(c5);
};

Texture2D<float4> shadow_depth : register(t1);
SamplerState _shadow_depth_sampler : register(s1);
Texture2D<float> shadow_cmp : register(t2);
SamplerComparisonState _shadow_cmp_sampler : register(s2);
Texture2D<float4> receivers : register(t3);
SamplerState _receivers_sampler : register(s3);

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
        float _257 = shadow_depth_point(param);
        float shadowMapDepth = _257;
        bool blocks = shadowMapDepth < (zReceiver - params_sampling.y);
        blockerSum += (blocks ? shadowMapDepth : 0.0f);
        numBlockers += float(blocks);
    }
    float _279;
    if (numBlockers > 0.0f)
    {
        _279 = blockerSum / numBlockers;
    }
    else
    {
        _279 = zReceiver;
    }
    avgBlockerDepth = _279;
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
    float3 _135 = float3(uv, reference);
    return shadow_cmp.SampleCmpLevelZero(_shadow_cmp_sampler, _135.xy, _135.z);
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
        float _218 = shadow_compare_bilinear(param, param_1);
        sum += _218;
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
    float _334 = PCF_Filter(param_4, param_5, param_6);
    return _334;
}

float shadow_visibility(float3 query)
{
    float3 param = query;
    float _339 = PCSS(param);
    return _339;
}

float receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _359 = shadow_visibility(param);
    return _359;
}

void frag_main()
{
    penumbra_texel_reads = 0.0f;
    float3 query = receivers.SampleLevel(_receivers_sampler, screen_uv, 0.0f).xyz;
    float3 param = query;
    float2 param_1 = floor(screen_uv * params_screen_size.xy);
    float _382 = receiver_visibility(param, param_1);
    float visible = _382;
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
