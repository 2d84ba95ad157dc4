static const float2 penumbra_POISSON_DISK[16] = { float2(-0.3564817905426025390625f, -0.7736518383026123046875f), float2(0.7706091403961181640625f, -0.476450383663177490234375f), float2(0.040970109403133392333984375f, -0.96095740795135498046875f), float2(0.013376322574913501739501953125f, 0.997840583324432373046875f), float2(0.591416180133819580078125f, -0.011377436108887195587158203125f), float2(0.1291187703609466552734375f, -0.02888503484427928924560546875f), float2(0.3763323128223419189453125f, 0.4415138661861419677734375f), float2(0.549356281757354736328125f, 0.793806552886962890625f), float2(-0.011186738498508930206298828125f, 0.4573924839496612548828125f), float2(0.784348905086517333984375f, 0.3635326325893402099609375f), float2(-0.797832071781158447265625f, -0.535640716552734375f), float2(0.480243146419525146484375f, -0.69643151760101318359375f), float2(-0.750289142131805419921875f, 0.620359599590301513671875f), float2(-0.95311391353607177734375f, -0.03544120490550994873046875f), float2(-0.4556185305118560791015625f, -0.09509353339672088623046875f), float2(0.12933044135570526123046875f, -0.57352435588836669921875f) };

cbuffer penumbra_ShadowParams : register(b0)
{
    float4 penumbra_params_shadow_map_size : packoffset(c0);
    float4 penumbra_params_light : packoffset(c1);
    float4 penumbra_params_sampling : packoffset(c2);
    float4 penumbra_params_screen_size : packoffset(c3);
    float4 penumbra_params_source_size : packoffset(c4);
    float4 penumbra_params_minmax_info : packoffset(c5);
};

Texture2D<float4> penumbra_shadow_depth : register(t1);
SamplerState _penumbra_shadow_depth_sampler : register(s1);
Texture2D<float> penumbra_shadow_cmp : register(t2);
SamplerComparisonState _penumbra_shadow_cmp_sampler : register(s2);

static float penumbra_texel_reads;

float penumbra_shadow_linear(float stored)
{
    return ((1.0f - stored) * penumbra_params_light.z) + (stored * penumbra_params_sampling.w);
}

float3 penumbra_clip_to_query(float4 light_clip_position)
{
    float2 ndc = light_clip_position.xy / light_clip_position.w.xx;
    float param = light_clip_position.z / light_clip_position.w;
    return float3(0.5f + (0.5f * ndc.x), 0.5f + ((-0.5f) * ndc.y), penumbra_shadow_linear(param));
}

float penumbra_shadow_depth_point(float2 uv)
{
    penumbra_texel_reads += 1.0f;
    float param = penumbra_shadow_depth.SampleLevel(_penumbra_shadow_depth_sampler, uv, 0.0f).x;
    return penumbra_shadow_linear(param);
}

void penumbra_FindBlocker(inout float avgBlockerDepth, inout float numBlockers, float2 uv, float zReceiver)
{
    float searchWidth = penumbra_params_light.w * (zReceiver - penumbra_params_light.z);
    float blockerSum = 0.0f;
    numBlockers = 0.0f;
    [loop]
    for (int i = 0; i < 16; i++)
    {
        float2 offset = penumbra_POISSON_DISK[i] * searchWidth;
        float2 param = uv + offset;
        float _266 = penumbra_shadow_depth_point(param);
        float shadowMapDepth = _266;
        bool blocks = shadowMapDepth < (zReceiver - penumbra_params_sampling.y);
        blockerSum += (blocks ? shadowMapDepth : 0.0f);
        numBlockers += float(blocks);
    }
    float _288;
    if (numBlockers > 0.0f)
    {
        _288 = blockerSum / numBlockers;
    }
    else
    {
        _288 = zReceiver;
    }
    avgBlockerDepth = _288;
}

float penumbra_shadow_encode(float z)
{
    return (z - penumbra_params_light.z) / (penumbra_params_sampling.w - penumbra_params_light.z);
}

float penumbra_shadow_reference(float z_receiver)
{
    float param = z_receiver - penumbra_params_sampling.y;
    return penumbra_shadow_encode(param);
}

float penumbra_shadow_compare_bilinear(float2 uv, float z_receiver)
{
    penumbra_texel_reads += 4.0f;
    float param = z_receiver;
    float reference = penumbra_shadow_reference(param);
    float3 _144 = float3(uv, reference);
    return penumbra_shadow_cmp.SampleCmpLevelZero(_penumbra_shadow_cmp_sampler, _144.xy, _144.z);
}

float penumbra_PCF_Filter(float2 uv, float zReceiver, float filterRadiusUV)
{
    float sum = 0.0f;
    [loop]
    for (int i = 0; i < 16; i++)
    {
        float2 offset = penumbra_POISSON_DISK[i] * filterRadiusUV;
        float2 param = uv + offset;
        float param_1 = zReceiver;
        float _227 = penumbra_shadow_compare_bilinear(param, param_1);
        sum += _227;
    }
    return sum / 16.0f;
}

float penumbra_PCSS(float3 coords)
{
    float2 uv = coords.xy;
    float zReceiver = coords.z;
    if (!(zReceiver > penumbra_params_light.z))
    {
        return 1.0f;
    }
    float avgBlockerDepth = 0.0f;
    float numBlockers = 0.0f;
    float2 param_2 = uv;
    float param_3 = zReceiver;
    float param;
    float param_1;
    penumbra_FindBlocker(param, param_1, param_2, param_3);
    avgBlockerDepth = param;
    numBlockers = param_1;
    if (numBlockers < 1.0f)
    {
        return 1.0f;
    }
    float filterRadiusUV = penumbra_params_light.w * (zReceiver - max(avgBlockerDepth, penumbra_params_light.z));
    float2 param_4 = uv;
    float param_5 = zReceiver;
    float param_6 = filterRadiusUV;
    float _343 = penumbra_PCF_Filter(param_4, param_5, param_6);
    return _343;
}

float penumbra_shadow_visibility(float3 query)
{
    float3 param = query;
    float _348 = penumbra_PCSS(param);
    return _348;
}

float penumbra_receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _368 = penumbra_shadow_visibility(param);
    return _368;
}

float penumbra_visibility(float4 light_clip_position)
{
    float2 pixel = 0.0f.xx;
    penumbra_texel_reads = 0.0f;
    float4 param = light_clip_position;
    float3 query = penumbra_clip_to_query(param);
    float3 param_1 = query;
    float2 param_2 = pixel;
    float _408 = penumbra_receiver_visibility(param_1, param_2);
    return _408;
}
