// penumbra_ShadowParams as Direct3D 9 constant registers
uniform float4 penumbra_params_shadow_map_size : register(c0);
uniform float4 penumbra_params_light : register(c1);
uniform float4 penumbra_params_sampling : register(c2);
uniform float4 penumbra_params_screen_size : register(c3);
uniform float4 penumbra_params_source_size : register(c4);
uniform float4 penumbra_params_minmax_info : register(c5);

uniform sampler2D penumbra_shadow_depth : register(s1);
uniform sampler2D penumbra_pcf_disk : register(s8);
uniform sampler2D penumbra_blocker_disk : register(s9);

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
    float param = tex2Dlod(penumbra_shadow_depth, float4(uv, 0.0, 0.0f)).x;
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
        float2 offset = tex2Dlod(penumbra_blocker_disk, float4(float2((float(i) + 0.5f) / 16.0f, 0.5f), 0.0, 0.0f)).xy * searchWidth;
        float2 param = uv + offset;
        float _296 = penumbra_shadow_depth_point(param);
        float shadowMapDepth = _296;
        bool blocks = shadowMapDepth < (zReceiver - penumbra_params_sampling.y);
        blockerSum += (blocks ? shadowMapDepth : 0.0f);
        numBlockers += float(blocks);
    }
    float _318;
    if (numBlockers > 0.0f)
    {
        _318 = blockerSum / numBlockers;
    }
    else
    {
        _318 = zReceiver;
    }
    avgBlockerDepth = _318;
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
    float2 texel = (uv * penumbra_params_shadow_map_size.xy) - 0.5f.xx;
    float2 corner = floor(texel);
    float2 weight = texel - corner;
    float2 uv00 = (corner + 0.5f.xx) * penumbra_params_shadow_map_size.zw;
    float2 uv11 = uv00 + penumbra_params_shadow_map_size.zw;
    float lit00 = float(reference <= tex2Dlod(penumbra_shadow_depth, float4(uv00, 0.0, 0.0f)).x);
    float lit10 = float(reference <= tex2Dlod(penumbra_shadow_depth, float4(float2(uv11.x, uv00.y), 0.0, 0.0f)).x);
    float lit01 = float(reference <= tex2Dlod(penumbra_shadow_depth, float4(float2(uv00.x, uv11.y), 0.0, 0.0f)).x);
    float lit11 = float(reference <= tex2Dlod(penumbra_shadow_depth, float4(uv11, 0.0, 0.0f)).x);
    return lerp(lerp(lit00, lit10, weight.x), lerp(lit01, lit11, weight.x), weight.y);
}

float penumbra_PCF_Filter(float2 uv, float zReceiver, float filterRadiusUV)
{
    float sum = 0.0f;
    [loop]
    for (int i = 0; i < 16; i++)
    {
        float2 offset = tex2Dlod(penumbra_pcf_disk, float4(float2((float(i) + 0.5f) / 16.0f, 0.5f), 0.0, 0.0f)).xy * filterRadiusUV;
        float2 param = uv + offset;
        float param_1 = zReceiver;
        float _253 = penumbra_shadow_compare_bilinear(param, param_1);
        sum += _253;
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
    float _373 = penumbra_PCF_Filter(param_4, param_5, param_6);
    return _373;
}

float penumbra_shadow_visibility(float3 query)
{
    float3 param = query;
    float _378 = penumbra_PCSS(param);
    return _378;
}

float penumbra_receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _398 = penumbra_shadow_visibility(param);
    return _398;
}

float penumbra_visibility(float4 light_clip_position)
{
    float2 pixel = 0.0f.xx;
    penumbra_texel_reads = 0.0f;
    float4 param = light_clip_position;
    float3 query = penumbra_clip_to_query(param);
    float3 param_1 = query;
    float2 param_2 = pixel;
    float _437 = penumbra_receiver_visibility(param_1, param_2);
    return _437;
}
