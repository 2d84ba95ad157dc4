// ShadowParams as Direct3D 9 constant registers
uniform float4 params_shadow_map_size : register(c0);
uniform float4 params_light : register(c1);
uniform float4 params_sampling : register(c2);
uniform float4 params_screen_size : register(c3);
uniform float4 params_source_size : register(c4);
uniform float4 params_minmax_info : register(c5);


uniform sampler2D shadow_depth : register(s1);
uniform sampler2D pcf_disk : register(s8);
uniform sampler2D blocker_disk : register(s9);
uniform sampler2D receivers : register(s3);

static float2 screen_uv;
static float4 visibility;

struct SPIRV_Cross_Input
{
    float2 screen_uv : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float4 visibility : COLOR0;
};

static float penumbra_texel_reads;

float shadow_linear(float stored)
{
    return ((1.0f - stored) * params_light.z) + (stored * params_sampling.w);
}

float shadow_depth_point(float2 uv)
{
    penumbra_texel_reads += 1.0f;
    float param = tex2Dlod(shadow_depth, float4(uv, 0.0, 0.0f)).x;
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
        float2 offset = tex2Dlod(blocker_disk, float4(float2((float(i) + 0.5f) / 16.0f, 0.5f), 0.0, 0.0f)).xy * searchWidth;
        float2 param = uv + offset;
        float _287 = shadow_depth_point(param);
        float shadowMapDepth = _287;
        bool blocks = shadowMapDepth < (zReceiver - params_sampling.y);
        blockerSum += (blocks ? shadowMapDepth : 0.0f);
        numBlockers += float(blocks);
    }
    float _309;
    if (numBlockers > 0.0f)
    {
        _309 = blockerSum / numBlockers;
    }
    else
    {
        _309 = zReceiver;
    }
    avgBlockerDepth = _309;
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
    float2 texel = (uv * params_shadow_map_size.xy) - 0.5f.xx;
    float2 corner = floor(texel);
    float2 weight = texel - corner;
    float2 uv00 = (corner + 0.5f.xx) * params_shadow_map_size.zw;
    float2 uv11 = uv00 + params_shadow_map_size.zw;
    float lit00 = float(reference <= tex2Dlod(shadow_depth, float4(uv00, 0.0, 0.0f)).x);
    float lit10 = float(reference <= tex2Dlod(shadow_depth, float4(float2(uv11.x, uv00.y), 0.0, 0.0f)).x);
    float lit01 = float(reference <= tex2Dlod(shadow_depth, float4(float2(uv00.x, uv11.y), 0.0, 0.0f)).x);
    float lit11 = float(reference <= tex2Dlod(shadow_depth, float4(uv11, 0.0, 0.0f)).x);
    return lerp(lerp(lit00, lit10, weight.x), lerp(lit01, lit11, weight.x), weight.y);
}

float PCF_Filter(float2 uv, float zReceiver, float filterRadiusUV)
{
    float sum = 0.0f;
    [loop]
    for (int i = 0; i < 16; i++)
    {
        float2 offset = tex2Dlod(pcf_disk, float4(float2((float(i) + 0.5f) / 16.0f, 0.5f), 0.0, 0.0f)).xy * filterRadiusUV;
        float2 param = uv + offset;
        float param_1 = zReceiver;
        float _244 = shadow_compare_bilinear(param, param_1);
        sum += _244;
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
    float _364 = PCF_Filter(param_4, param_5, param_6);
    return _364;
}

float shadow_visibility(float3 query)
{
    float3 param = query;
    float _369 = PCSS(param);
    return _369;
}

float receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _389 = shadow_visibility(param);
    return _389;
}

void frag_main()
{
    penumbra_texel_reads = 0.0f;
    float3 query = tex2Dlod(receivers, float4(screen_uv, 0.0, 0.0f)).xyz;
    float3 param = query;
    float2 param_1 = floor(screen_uv * params_screen_size.xy);
    float _411 = receiver_visibility(param, param_1);
    float visible = _411;
    visibility = float4(visible, penumbra_texel_reads, 0.0f, 0.0f);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    screen_uv = stage_input.screen_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.visibility = float4(visibility);
    return stage_output;
}
