static const float2 penumbra_PCF_DISK[16] = { float2(-0.94201624393463134765625f, -0.39906215667724609375f), float2(0.94558608531951904296875f, -0.768907248973846435546875f), float2(-0.094184100627899169921875f, -0.929388701915740966796875f), float2(0.34495937824249267578125f, 0.29387760162353515625f), float2(-0.91588580608367919921875f, 0.4577143192291259765625f), float2(-0.8154423236846923828125f, -0.87912464141845703125f), float2(-0.38277542591094970703125f, 0.2767684459686279296875f), float2(0.9748439788818359375f, 0.7564837932586669921875f), float2(0.4432332515716552734375f, -0.9751155376434326171875f), float2(0.5374298095703125f, -0.473734200000762939453125f), float2(-0.2649691104888916015625f, -0.418930232524871826171875f), float2(0.79197514057159423828125f, 0.19090187549591064453125f), float2(-0.24188840389251708984375f, 0.997065067291259765625f), float2(-0.8140995502471923828125f, 0.91437590122222900390625f), float2(0.1998412609100341796875f, 0.786413669586181640625f), float2(0.14383161067962646484375f, -0.141007900238037109375f) };

cbuffer penumbra_ShadowParams : register(b0)
{
    float4 penumbra_params_shadow_map_size : packoffset(c0);
    float4 penumbra_params_light : packoffset(c1);
    float4 penumbra_params_sampling : packoffset(c2);
    float4 penumbra_params_screen_size : packoffset(c3);
    float4 penumbra_params_source_size : packoffset(c4);
    float4 penumbra_params_minmax_info : packoffset(c5);
};

Texture2D<float> penumbra_shadow_cmp : register(t2);
SamplerComparisonState _penumbra_shadow_cmp_sampler : register(s2);
Texture2D<float4> penumbra_shadow_depth : register(t1);
SamplerState _penumbra_shadow_depth_sampler : register(s1);
Texture2D<float4> penumbra_shadow_minmax : register(t4);
SamplerState _penumbra_shadow_minmax_sampler : register(s4);

static float penumbra_texel_reads;

float3 penumbra_clip_to_query(float4 light_clip_position)
{
    float2 ndc = light_clip_position.xy / light_clip_position.w.xx;
    return float3(0.5f + (0.5f * ndc.x), 0.5f + ((-0.5f) * ndc.y), light_clip_position.w);
}

float penumbra_shadow_reference(float z_receiver)
{
    return (z_receiver - penumbra_params_sampling.y) * penumbra_params_sampling.z;
}

float4 penumbra_minmax_clip_window(float2 first, float2 last)
{
    return float4(max(first, 0.0f.xx), min(last, penumbra_params_shadow_map_size.xy - 1.0f.xx));
}

bool penumbra_minmax_window_empty(float4 window)
{
    return any(bool2(window.xy.x > window.zw.x, window.xy.y > window.zw.y));
}

float penumbra_minmax_level_spanning(float4 window, float nodes)
{
    float level = 0.0f;
    float inv_span = 1.0f;
    [loop]
    for (int k = 0; k < 16; k++)
    {
        float2 spanned = floor(window.zw * inv_span) - floor(window.xy * inv_span);
        if (max(spanned.x, spanned.y) < nodes)
        {
            break;
        }
        level += 1.0f;
        inv_span *= 0.5f;
    }
    return level;
}

float penumbra_shadow_texel(float2 texel)
{
    penumbra_texel_reads += 1.0f;
    return penumbra_shadow_depth.SampleLevel(_penumbra_shadow_depth_sampler, (texel + 0.5f.xx) * penumbra_params_shadow_map_size.zw, 0.0f).x;
}

float2 penumbra_minmax_node(float level, float2 node)
{
    if (level < 0.5f)
    {
        float2 param = node;
        float _157 = penumbra_shadow_texel(param);
        float depth = _157;
        return float2(depth, depth);
    }
    penumbra_texel_reads += 1.0f;
    float2 uv = (node + 0.5f.xx) * exp2(level - penumbra_params_minmax_info.x);
    return penumbra_shadow_minmax.SampleLevel(_penumbra_shadow_minmax_sampler, uv, level - 1.0f).xy;
}

float penumbra_minmax_texel_count(float4 part)
{
    return ((part.z - part.x) + 1.0f) * ((part.w - part.y) + 1.0f);
}

bool penumbra_minmax_find_blocker(out float zBlocker, float2 uv, float zReceiver, float reference)
{
    zBlocker = zReceiver;
    float searchWidth = (penumbra_params_light.w * (zReceiver - penumbra_params_light.z)) / zReceiver;
    float2 map_size = penumbra_params_shadow_map_size.xy;
    float2 param = floor((uv - searchWidth.xx) * map_size);
    float2 param_1 = floor((uv + searchWidth.xx) * map_size);
    float4 window = penumbra_minmax_clip_window(param, param_1);
    float4 param_2 = window;
    if (penumbra_minmax_window_empty(param_2))
    {
        return false;
    }
    float4 param_3 = window;
    float param_4 = 3.0f;
    float level = penumbra_minmax_level_spanning(param_3, param_4);
    float span = exp2(level);
    float2 first = floor(window.xy / span.xx);
    float depth_sum = 0.0f;
    float texels = 0.0f;
    [loop]
    for (int j = 0; j < 3; j++)
    {
        [loop]
        for (int i = 0; i < 3; i++)
        {
            float2 node = first + float2(float(i), float(j));
            float4 part = float4(max(node * span, window.xy), min(((node * span) + span.xx) - 1.0f.xx, window.zw));
            float4 param_5 = part;
            if (!penumbra_minmax_window_empty(param_5))
            {
                float param_6 = level;
                float2 param_7 = node;
                float2 _478 = penumbra_minmax_node(param_6, param_7);
                float node_min = _478.x;
                if (node_min < reference)
                {
                    float4 param_8 = part;
                    float weight = penumbra_minmax_texel_count(param_8);
                    depth_sum += (node_min * weight);
                    texels += weight;
                }
            }
        }
    }
    if (texels < 0.5f)
    {
        return false;
    }
    zBlocker = (depth_sum / texels) * penumbra_params_sampling.w;
    return true;
}

float penumbra_PenumbraSize(float zReceiver, float zBlocker)
{
    return (zReceiver - zBlocker) / zBlocker;
}

float penumbra_shadow_compare_bilinear(float2 uv, float z_receiver)
{
    penumbra_texel_reads += 4.0f;
    float param = z_receiver;
    float reference = penumbra_shadow_reference(param);
    float3 _121 = float3(uv, reference);
    return penumbra_shadow_cmp.SampleCmpLevelZero(_penumbra_shadow_cmp_sampler, _121.xy, _121.z);
}

float penumbra_PCF_Filter(float2 uv, float zReceiver, float filterRadiusUV)
{
    float sum = 0.0f;
    [loop]
    for (int i = 0; i < 16; i++)
    {
        float2 offset = penumbra_PCF_DISK[i] * filterRadiusUV;
        float2 param = uv + offset;
        float param_1 = zReceiver;
        float _351 = penumbra_shadow_compare_bilinear(param, param_1);
        sum += _351;
    }
    return sum / 16.0f;
}

float penumbra_shadow_visibility(float3 query)
{
    if (!(query.z > penumbra_params_light.z))
    {
        return 1.0f;
    }
    float zBlocker = 0.0f;
    float param = query.z;
    float2 param_2 = query.xy;
    float param_3 = query.z;
    float param_4 = penumbra_shadow_reference(param);
    float param_1;
    bool _537 = penumbra_minmax_find_blocker(param_1, param_2, param_3, param_4);
    zBlocker = param_1;
    if (!_537)
    {
        return 1.0f;
    }
    zBlocker = max(zBlocker, penumbra_params_light.z);
    float param_5 = query.z;
    float param_6 = zBlocker;
    float filterRadiusUV = ((penumbra_PenumbraSize(param_5, param_6) * penumbra_params_light.w) * penumbra_params_light.z) / query.z;
    float2 param_7 = query.xy;
    float param_8 = query.z;
    float param_9 = filterRadiusUV;
    float _571 = penumbra_PCF_Filter(param_7, param_8, param_9);
    return _571;
}

float penumbra_receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _591 = penumbra_shadow_visibility(param);
    return _591;
}

float penumbra_visibility(float4 light_clip_position)
{
    float2 pixel = 0.0f.xx;
    penumbra_texel_reads = 0.0f;
    float4 param = light_clip_position;
    float3 query = penumbra_clip_to_query(param);
    float3 param_1 = query;
    float2 param_2 = pixel;
    float _624 = penumbra_receiver_visibility(param_1, param_2);
    return _624;
}
