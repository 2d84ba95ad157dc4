struct penumbra_MinmaxCursor
{
    float2 node;
    float level;
    float span;
    float2 first_root;
    float start;
    bool climbed;
    bool done;
};

// penumbra_ShadowParams as Direct3D 9 constant registers
uniform float4 penumbra_params_shadow_map_size : register(c0);
uniform float4 penumbra_params_light : register(c1);
uniform float4 penumbra_params_sampling : register(c2);
uniform float4 penumbra_params_screen_size : register(c3);
uniform float4 penumbra_params_source_size : register(c4);
uniform float4 penumbra_params_minmax_info : register(c5);

uniform sampler2D penumbra_shadow_depth : register(s1);
uniform sampler2D penumbra_shadow_minmax : register(s4);

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

penumbra_MinmaxCursor penumbra_minmax_begin(float4 window)
{
    float4 param = window;
    float param_1 = 2.0f;
    penumbra_MinmaxCursor cursor;
    cursor.level = penumbra_minmax_level_spanning(param, param_1);
    cursor.span = exp2(cursor.level);
    cursor.start = cursor.level;
    cursor.first_root = floor(window.xy / cursor.span.xx);
    cursor.node = cursor.first_root;
    cursor.climbed = false;
    cursor.done = false;
    return cursor;
}

float4 penumbra_minmax_node_part(penumbra_MinmaxCursor cursor, float4 window)
{
    float2 first = cursor.node * cursor.span;
    return float4(max(first, window.xy), min((first + cursor.span.xx) - 1.0f.xx, window.zw));
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
        float _140 = penumbra_shadow_texel(param);
        float depth = _140;
        return float2(depth, depth);
    }
    penumbra_texel_reads += 1.0f;
    float2 uv = (node + 0.5f.xx) * exp2(level - penumbra_params_minmax_info.x);
    return tex2Dlod(penumbra_shadow_minmax, float4(uv, 0.0, level - 1.0f)).xy;
}

float2 penumbra_minmax_cursor_read(penumbra_MinmaxCursor cursor)
{
    float param = cursor.level;
    float2 param_1 = cursor.node;
    float2 _321 = penumbra_minmax_node(param, param_1);
    return _321;
}

float penumbra_minmax_texel_count(float4 part)
{
    return ((part.z - part.x) + 1.0f) * ((part.w - part.y) + 1.0f);
}

void penumbra_minmax_descend(inout penumbra_MinmaxCursor cursor)
{
    cursor.node *= 2.0f;
    cursor.level -= 1.0f;
    cursor.span *= 0.5f;
}

void penumbra_minmax_next(inout penumbra_MinmaxCursor cursor)
{
    bool root = cursor.level >= cursor.start;
    float2 _344;
    if (root)
    {
        _344 = cursor.first_root;
    }
    else
    {
        _344 = floor(cursor.node * 0.5f) * 2.0f;
    }
    float2 first_sibling = _344;
    float2 offset = cursor.node - first_sibling;
    cursor.climbed = false;
    if (offset.x < 0.5f)
    {
        cursor.node.x += 1.0f;
    }
    else
    {
        if (offset.y < 0.5f)
        {
            cursor.node = float2(first_sibling.x, cursor.node.y + 1.0f);
        }
        else
        {
            if (root)
            {
                cursor.done = true;
            }
            else
            {
                cursor.node = floor(cursor.node * 0.5f);
                cursor.level += 1.0f;
                cursor.span *= 2.0f;
                cursor.climbed = true;
            }
        }
    }
}

float penumbra_minmax_pcf_count(float2 first, float reference)
{
    float count = 0.0f;
    float2 param = first;
    float2 param_1 = first + 5.0f.xx;
    float4 window = penumbra_minmax_clip_window(param, param_1);
    float4 param_2 = window;
    if (penumbra_minmax_window_empty(param_2))
    {
        return 0.0f;
    }
    float4 param_3 = window;
    penumbra_MinmaxCursor cursor = penumbra_minmax_begin(param_3);
    [loop]
    for (int loop_inner = 0; all(bool2(loop_inner < 149, !cursor.done)); loop_inner++)
    {
        penumbra_MinmaxCursor param_4 = cursor;
        float4 param_5 = window;
        float4 part = penumbra_minmax_node_part(param_4, param_5);
        bool descend = false;
        bool _448 = !cursor.climbed;
        bool _455;
        if (_448)
        {
            float4 param_6 = part;
            _455 = !penumbra_minmax_window_empty(param_6);
        }
        else
        {
            _455 = _448;
        }
        if (_455)
        {
            penumbra_MinmaxCursor param_7 = cursor;
            float2 _461 = penumbra_minmax_cursor_read(param_7);
            float2 range = _461;
            if (range.y < reference)
            {
                float4 param_8 = part;
                count += penumbra_minmax_texel_count(param_8);
            }
            else
            {
                bool _477 = reference > range.x;
                bool _483;
                if (_477)
                {
                    _483 = cursor.level > 0.5f;
                }
                else
                {
                    _483 = _477;
                }
                descend = _483;
            }
        }
        if (descend)
        {
            penumbra_MinmaxCursor param_9 = cursor;
            penumbra_minmax_descend(param_9);
            cursor = param_9;
        }
        else
        {
            penumbra_MinmaxCursor param_10 = cursor;
            penumbra_minmax_next(param_10);
            cursor = param_10;
        }
    }
    return count;
}

float penumbra_shadow_visibility(float3 query)
{
    float2 first = floor(query.xy * penumbra_params_shadow_map_size.xy) - 3.0f.xx;
    float param = query.z;
    float2 param_1 = first;
    float param_2 = penumbra_shadow_reference(param);
    float _520 = penumbra_minmax_pcf_count(param_1, param_2);
    float count = _520;
    float _523;
    if (count > 0.0f)
    {
        _523 = (36.0f - count) * 0.02777777798473834991455078125f;
    }
    else
    {
        _523 = 1.0f;
    }
    return _523;
}

float penumbra_receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _552 = penumbra_shadow_visibility(param);
    return _552;
}

float penumbra_visibility(float4 light_clip_position)
{
    float2 pixel = 0.0f.xx;
    penumbra_texel_reads = 0.0f;
    float4 param = light_clip_position;
    float3 query = penumbra_clip_to_query(param);
    float3 param_1 = query;
    float2 param_2 = pixel;
    float _585 = penumbra_receiver_visibility(param_1, param_2);
    return _585;
}
