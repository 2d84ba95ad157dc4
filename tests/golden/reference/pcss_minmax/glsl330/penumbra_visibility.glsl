const vec2 penumbra_PCF_DISK[16] = vec2[](vec2(-0.94201624393463134765625, -0.39906215667724609375), vec2(0.94558608531951904296875, -0.768907248973846435546875), vec2(-0.094184100627899169921875, -0.929388701915740966796875), vec2(0.34495937824249267578125, 0.29387760162353515625), vec2(-0.91588580608367919921875, 0.4577143192291259765625), vec2(-0.8154423236846923828125, -0.87912464141845703125), vec2(-0.38277542591094970703125, 0.2767684459686279296875), vec2(0.9748439788818359375, 0.7564837932586669921875), vec2(0.4432332515716552734375, -0.9751155376434326171875), vec2(0.5374298095703125, -0.473734200000762939453125), vec2(-0.2649691104888916015625, -0.418930232524871826171875), vec2(0.79197514057159423828125, 0.19090187549591064453125), vec2(-0.24188840389251708984375, 0.997065067291259765625), vec2(-0.8140995502471923828125, 0.91437590122222900390625), vec2(0.1998412609100341796875, 0.786413669586181640625), vec2(0.14383161067962646484375, -0.141007900238037109375));

struct penumbra_ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
    vec4 source_size;
    vec4 minmax_info;
};

uniform penumbra_ShadowParams penumbra_params;

uniform sampler2DShadow penumbra_shadow_cmp;
uniform sampler2D penumbra_shadow_depth;
uniform sampler2D penumbra_shadow_minmax;

float penumbra_texel_reads;

vec3 penumbra_clip_to_query(vec4 light_clip_position)
{
    vec2 ndc = light_clip_position.xy / vec2(light_clip_position.w);
    return vec3(0.5 + (0.5 * ndc.x), 0.5 + (0.5 * ndc.y), light_clip_position.w);
}

float penumbra_shadow_reference(float z_receiver)
{
    return (z_receiver - penumbra_params.sampling.y) * penumbra_params.sampling.z;
}

vec4 penumbra_minmax_clip_window(vec2 first, vec2 last)
{
    return vec4(max(first, vec2(0.0)), min(last, penumbra_params.shadow_map_size.xy - vec2(1.0)));
}

bool penumbra_minmax_window_empty(vec4 window)
{
    return any(greaterThan(window.xy, window.zw));
}

float penumbra_minmax_level_spanning(vec4 window, float nodes)
{
    float level = 0.0;
    float inv_span = 1.0;
    for (int k = 0; k < 16; k++)
    {
        vec2 spanned = floor(window.zw * inv_span) - floor(window.xy * inv_span);
        if (max(spanned.x, spanned.y) < nodes)
        {
            break;
        }
        level += 1.0;
        inv_span *= 0.5;
    }
    return level;
}

float penumbra_shadow_texel(vec2 texel)
{
    penumbra_texel_reads += 1.0;
    return textureLod(penumbra_shadow_depth, (texel + vec2(0.5)) * penumbra_params.shadow_map_size.zw, 0.0).x;
}

vec2 penumbra_minmax_node(float level, vec2 node)
{
    if (level < 0.5)
    {
        vec2 param = node;
        float _157 = penumbra_shadow_texel(param);
        float depth = _157;
        return vec2(depth, depth);
    }
    penumbra_texel_reads += 1.0;
    vec2 uv = (node + vec2(0.5)) * exp2(level - penumbra_params.minmax_info.x);
    return textureLod(penumbra_shadow_minmax, uv, level - 1.0).xy;
}

float penumbra_minmax_texel_count(vec4 part)
{
    return ((part.z - part.x) + 1.0) * ((part.w - part.y) + 1.0);
}

bool penumbra_minmax_find_blocker(out float zBlocker, vec2 uv, float zReceiver, float reference)
{
    zBlocker = zReceiver;
    float searchWidth = (penumbra_params.light.w * (zReceiver - penumbra_params.light.z)) / zReceiver;
    vec2 map_size = penumbra_params.shadow_map_size.xy;
    vec2 param = floor((uv - vec2(searchWidth)) * map_size);
    vec2 param_1 = floor((uv + vec2(searchWidth)) * map_size);
    vec4 window = penumbra_minmax_clip_window(param, param_1);
    vec4 param_2 = window;
    if (penumbra_minmax_window_empty(param_2))
    {
        return false;
    }
    vec4 param_3 = window;
    float param_4 = 3.0;
    float level = penumbra_minmax_level_spanning(param_3, param_4);
    float span = exp2(level);
    vec2 first = floor(window.xy / vec2(span));
    float depth_sum = 0.0;
    float texels = 0.0;
    for (int j = 0; j < 3; j++)
    {
        for (int i = 0; i < 3; i++)
        {
            vec2 node = first + vec2(float(i), float(j));
            vec4 part = vec4(max(node * span, window.xy), min(((node * span) + vec2(span)) - vec2(1.0), window.zw));
            vec4 param_5 = part;
            if (!penumbra_minmax_window_empty(param_5))
            {
                float param_6 = level;
                vec2 param_7 = node;
                vec2 _478 = penumbra_minmax_node(param_6, param_7);
                float node_min = _478.x;
                if (node_min < reference)
                {
                    vec4 param_8 = part;
                    float weight = penumbra_minmax_texel_count(param_8);
                    depth_sum += (node_min * weight);
                    texels += weight;
                }
            }
        }
    }
    if (texels < 0.5)
    {
        return false;
    }
    zBlocker = (depth_sum / texels) * penumbra_params.sampling.w;
    return true;
}

float penumbra_PenumbraSize(float zReceiver, float zBlocker)
{
    return (zReceiver - zBlocker) / zBlocker;
}

float penumbra_shadow_compare_bilinear(vec2 uv, float z_receiver)
{
    penumbra_texel_reads += 4.0;
    float param = z_receiver;
    float reference = penumbra_shadow_reference(param);
    vec3 _121 = vec3(uv, reference);
    return textureLod(penumbra_shadow_cmp, vec3(_121.xy, _121.z), 0.0);
}

float penumbra_PCF_Filter(vec2 uv, float zReceiver, float filterRadiusUV)
{
    float sum = 0.0;
    for (int i = 0; i < 16; i++)
    {
        vec2 offset = penumbra_PCF_DISK[i] * filterRadiusUV;
        vec2 param = uv + offset;
        float param_1 = zReceiver;
        float _351 = penumbra_shadow_compare_bilinear(param, param_1);
        sum += _351;
    }
    return sum / 16.0;
}

float penumbra_shadow_visibility(vec3 query)
{
    if (!(query.z > penumbra_params.light.z))
    {
        return 1.0;
    }
    float zBlocker = 0.0;
    float param = query.z;
    vec2 param_2 = query.xy;
    float param_3 = query.z;
    float param_4 = penumbra_shadow_reference(param);
    float param_1;
    bool _537 = penumbra_minmax_find_blocker(param_1, param_2, param_3, param_4);
    zBlocker = param_1;
    if (!_537)
    {
        return 1.0;
    }
    zBlocker = max(zBlocker, penumbra_params.light.z);
    float param_5 = query.z;
    float param_6 = zBlocker;
    float filterRadiusUV = ((penumbra_PenumbraSize(param_5, param_6) * penumbra_params.light.w) * penumbra_params.light.z) / query.z;
    vec2 param_7 = query.xy;
    float param_8 = query.z;
    float param_9 = filterRadiusUV;
    float _571 = penumbra_PCF_Filter(param_7, param_8, param_9);
    return _571;
}

float penumbra_receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _591 = penumbra_shadow_visibility(param);
    return _591;
}

float penumbra_visibility(vec4 light_clip_position)
{
    vec2 pixel = vec2(0.0);
    penumbra_texel_reads = 0.0;
    vec4 param = light_clip_position;
    vec3 query = penumbra_clip_to_query(param);
    vec3 param_1 = query;
    vec2 param_2 = pixel;
    float _623 = penumbra_receiver_visibility(param_1, param_2);
    return _623;
}
