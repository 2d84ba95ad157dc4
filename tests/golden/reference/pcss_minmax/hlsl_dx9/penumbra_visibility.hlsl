// penumbra_ShadowParams as Direct3D 9 constant registers
uniform float4 penumbra_params_shadow_map_size : register(c0);
uniform float4 penumbra_params_light : register(c1);
uniform float4 penumbra_params_sampling : register(c2);
uniform float4 penumbra_params_screen_size : register(c3);
uniform float4 penumbra_params_source_size : register(c4);
uniform float4 penumbra_params_minmax_info : register(c5);

uniform sampler2D penumbra_shadow_depth : register(s1);
uniform sampler2D penumbra_shadow_minmax : register(s4);
uniform sampler2D penumbra_pcf_disk : register(s8);

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
    return tex2Dlod(penumbra_shadow_depth, float4((texel + 0.5f.xx) * penumbra_params_shadow_map_size.zw, 0.0, 0.0f)).x;
}

float2 penumbra_minmax_node(float level, float2 node)
{
    if (level < 0.5f)
    {
        float2 param = node;
        float _227 = penumbra_shadow_texel(param);
        float depth = _227;
        return float2(depth, depth);
    }
    penumbra_texel_reads += 1.0f;
    float2 uv = (node + 0.5f.xx) * exp2(level - penumbra_params_minmax_info.x);
    return tex2Dlod(penumbra_shadow_minmax, float4(uv, 0.0, level - 1.0f)).xy;
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
                float2 _501 = penumbra_minmax_node(param_6, param_7);
                float node_min = _501.x;
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
        float _375 = penumbra_shadow_compare_bilinear(param, param_1);
        sum += _375;
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
    bool _560 = penumbra_minmax_find_blocker(param_1, param_2, param_3, param_4);
    zBlocker = param_1;
    if (!_560)
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
    float _594 = penumbra_PCF_Filter(param_7, param_8, param_9);
    return _594;
}

float penumbra_receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _614 = penumbra_shadow_visibility(param);
    return _614;
}

float penumbra_visibility(float4 light_clip_position)
{
    float2 pixel = 0.0f.xx;
    penumbra_texel_reads = 0.0f;
    float4 param = light_clip_position;
    float3 query = penumbra_clip_to_query(param);
    float3 param_1 = query;
    float2 param_2 = pixel;
    float _647 = penumbra_receiver_visibility(param_1, param_2);
    return _647;
}
