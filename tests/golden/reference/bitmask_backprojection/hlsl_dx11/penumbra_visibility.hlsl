struct penumbra_BackprojectionState
{
    uint rows[8];
    int set;
};

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

float penumbra_shadow_compare_point(float2 uv, float z_receiver)
{
    penumbra_texel_reads += 1.0f;
    float param = z_receiver;
    return float(penumbra_shadow_reference(param) <= penumbra_shadow_depth.SampleLevel(_penumbra_shadow_depth_sampler, uv, 0.0f).x);
}

float penumbra_backprojection_limit(float3 query)
{
    float param = query.z;
    return min(penumbra_shadow_reference(param), query.z * penumbra_params_sampling.z);
}

float2 penumbra_minmax_top_node()
{
    penumbra_texel_reads += 1.0f;
    return penumbra_shadow_minmax.SampleLevel(_penumbra_shadow_minmax_sampler, 0.5f.xx, penumbra_params_minmax_info.x - 1.0f).xy;
}

float4 penumbra_minmax_clip_window(float2 first, float2 last)
{
    return float4(max(first, 0.0f.xx), min(last, penumbra_params_shadow_map_size.xy - 1.0f.xx));
}

float4 penumbra_backprojection_window(float3 query, float z_min)
{
    float half_width = ((penumbra_params_light.w * penumbra_params_light.z) * (query.z - z_min)) / (query.z * z_min);
    float2 map_size = penumbra_params_shadow_map_size.xy;
    float2 param = floor((query.xy - half_width.xx) * map_size) - 1.0f.xx;
    float2 param_1 = floor((query.xy + half_width.xx) * map_size) + 1.0f.xx;
    return penumbra_minmax_clip_window(param, param_1);
}

bool penumbra_minmax_window_empty(float4 window)
{
    return any(bool2(window.xy.x > window.zw.x, window.xy.y > window.zw.y));
}

bool penumbra_backprojection_start(float3 query, inout float limit, inout float4 window)
{
    float3 param = query;
    limit = penumbra_backprojection_limit(param);
    float2 _941 = penumbra_minmax_top_node();
    float map_min = _941.x;
    float3 param_1 = query;
    float param_2 = map_min * penumbra_params_sampling.w;
    window = penumbra_backprojection_window(param_1, param_2);
    float4 param_3 = window;
    bool empty = penumbra_minmax_window_empty(param_3);
    return (map_min < limit) && (!empty);
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
    return penumbra_shadow_depth.SampleLevel(_penumbra_shadow_depth_sampler, (texel + 0.5f.xx) * penumbra_params_shadow_map_size.zw, 0.0f).x;
}

float2 penumbra_minmax_node(float level, float2 node)
{
    if (level < 0.5f)
    {
        float2 param = node;
        float _385 = penumbra_shadow_texel(param);
        float depth = _385;
        return float2(depth, depth);
    }
    penumbra_texel_reads += 1.0f;
    float2 uv = (node + 0.5f.xx) * exp2(level - penumbra_params_minmax_info.x);
    return penumbra_shadow_minmax.SampleLevel(_penumbra_shadow_minmax_sampler, uv, level - 1.0f).xy;
}

float2 penumbra_minmax_cursor_read(penumbra_MinmaxCursor cursor)
{
    float param = cursor.level;
    float2 param_1 = cursor.node;
    float2 _577 = penumbra_minmax_node(param, param_1);
    return _577;
}

float4 penumbra_minmax_node_texels(penumbra_MinmaxCursor cursor)
{
    float2 first = cursor.node * cursor.span;
    float2 param = first;
    float2 param_1 = (first + cursor.span.xx) - 1.0f.xx;
    return penumbra_minmax_clip_window(param, param_1);
}

float penumbra_backprojection_gain(float z, float z_receiver)
{
    return (z * z_receiver) / (z_receiver - z);
}

float penumbra_backprojection_to_slope()
{
    return penumbra_params_light.y / penumbra_params_light.z;
}

float4 penumbra_backprojection_project(float4 texels, float z, float3 query)
{
    float param = z;
    float param_1 = query.z;
    float scale = penumbra_backprojection_gain(param, param_1) * penumbra_backprojection_to_slope();
    float4 corners = float4(texels.xy, texels.zw + 1.0f.xx) * penumbra_params_shadow_map_size.zwzw;
    return (corners - query.xyxy) * scale;
}

bool penumbra_backprojection_touches(float4 rect)
{
    float4 _712 = rect * float4(1.0f, 1.0f, -1.0f, -1.0f);
    float4 _715 = penumbra_params_light.x.xxxx;
    return all(bool4(_712.x <= _715.x, _712.y <= _715.y, _712.z <= _715.z, _712.w <= _715.w));
}

int penumbra_bitmask_popcount(inout uint x)
{
    x -= ((x >> 1u) & 1431655765u);
    x = (x & 858993459u) + ((x >> 2u) & 858993459u);
    x = (x + (x >> 4u)) & 252645135u;
    return int((x * 16843009u) >> 24u);
}

penumbra_BackprojectionState penumbra_backprojection_add(inout penumbra_BackprojectionState state, float4 rect)
{
    float g = 8.0f;
    float4 t = ((rect + penumbra_params_light.x.xxxx) * ((g * g) / (2.0f * penumbra_params_light.x))) - float4(0.5625f, 0.5625f, 0.4375f, 0.4375f);
    int first_row = int(clamp(ceil((t.y - (g - 1.0f)) / g), 0.0f, g));
    int last_row = int(clamp(floor(t.w / g), -1.0f, g - 1.0f));
    [loop]
    for (int r = first_row; r <= last_row; r++)
    {
        float row = float(r);
        float first = max(ceil((t.x - row) / g), ceil(t.y - (row * g)));
        float last = min(floor((t.z - row) / g), floor(t.w - (row * g)));
        first = clamp(first, 0.0f, g);
        last = clamp(last, -1.0f, g - 1.0f);
        if (first > last)
        {
            continue;
        }
        uint mask = (2u << uint(last)) - (1u << uint(first));
        uint fresh = mask & (~state.rows[r]);
        state.rows[r] |= fresh;
        uint param = fresh;
        int _362 = penumbra_bitmask_popcount(param);
        state.set += _362;
    }
    return state;
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
    float2 _600;
    if (root)
    {
        _600 = cursor.first_root;
    }
    else
    {
        _600 = floor(cursor.node * 0.5f) * 2.0f;
    }
    float2 first_sibling = _600;
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

bool penumbra_backprojection_covered(penumbra_BackprojectionState state)
{
    return state.set >= 64;
}

penumbra_BackprojectionState penumbra_backprojection_walk(float3 query, float4 window, float limit, inout penumbra_BackprojectionState state)
{
    float visits = 0.0f;
    float4 param = window;
    penumbra_MinmaxCursor cursor = penumbra_minmax_begin(param);
    [loop]
    for (int loop_outer = 0; all(bool2(loop_outer < 1, !cursor.done)); loop_outer++)
    {
        [loop]
        for (int loop_middle = 0; all(bool2(loop_middle < 129, !cursor.done)); loop_middle++)
        {
            [loop]
            for (int loop_inner = 0; all(bool2(loop_inner < 255, !cursor.done)); loop_inner++)
            {
                bool descend = false;
                if (!cursor.climbed)
                {
                    visits += 1.0f;
                }
                bool _822 = !cursor.climbed;
                bool _833;
                if (_822)
                {
                    penumbra_MinmaxCursor param_1 = cursor;
                    float4 param_2 = window;
                    float4 param_3 = penumbra_minmax_node_part(param_1, param_2);
                    _833 = !penumbra_minmax_window_empty(param_3);
                }
                else
                {
                    _833 = _822;
                }
                if (_833)
                {
                    penumbra_MinmaxCursor param_4 = cursor;
                    float2 _839 = penumbra_minmax_cursor_read(param_4);
                    float2 range = _839;
                    penumbra_MinmaxCursor param_5 = cursor;
                    float4 texels = penumbra_minmax_node_texels(param_5);
                    float4 param_6 = texels;
                    float param_7 = range.x * penumbra_params_sampling.w;
                    float3 param_8 = query;
                    float4 rect = penumbra_backprojection_project(param_6, param_7, param_8);
                    float4 param_9 = rect;
                    bool touches = penumbra_backprojection_touches(param_9);
                    if ((range.x < limit) && touches)
                    {
                        bool _872 = range.y < limit;
                        bool _880;
                        if (_872)
                        {
                            _880 = range.x == range.y;
                        }
                        else
                        {
                            _880 = _872;
                        }
                        bool one_patch = _880;
                        descend = !one_patch;
                        if (one_patch)
                        {
                            penumbra_BackprojectionState param_10 = state;
                            float4 param_11 = rect;
                            penumbra_BackprojectionState _890 = penumbra_backprojection_add(param_10, param_11);
                            state = _890;
                        }
                    }
                }
                if (descend)
                {
                    penumbra_MinmaxCursor param_12 = cursor;
                    penumbra_minmax_descend(param_12);
                    cursor = param_12;
                }
                else
                {
                    penumbra_MinmaxCursor param_13 = cursor;
                    penumbra_minmax_next(param_13);
                    cursor = param_13;
                }
                penumbra_BackprojectionState param_14 = state;
                bool covered = penumbra_backprojection_covered(param_14);
                cursor.done = (cursor.done || covered) || (visits >= 16384.0f);
            }
        }
    }
    return state;
}

float penumbra_shadow_visibility(float3 query)
{
    if (!(penumbra_params_light.x > 0.0f))
    {
        float2 param = query.xy;
        float param_1 = query.z;
        float _975 = penumbra_shadow_compare_point(param, param_1);
        return _975;
    }
    float3 param_2 = query;
    float param_3;
    float4 param_4;
    bool _983 = penumbra_backprojection_start(param_2, param_3, param_4);
    float limit = param_3;
    float4 window = param_4;
    if (!_983)
    {
        return 1.0f;
    }
    penumbra_BackprojectionState state;
    [loop]
    for (int r = 0; r < 8; r++)
    {
        state.rows[r] = 0u;
    }
    state.set = 0;
    float3 param_5 = query;
    float4 param_6 = window;
    float param_7 = limit;
    penumbra_BackprojectionState param_8 = state;
    penumbra_BackprojectionState _1013 = penumbra_backprojection_walk(param_5, param_6, param_7, param_8);
    state = _1013;
    return 1.0f - (float(state.set) / 64.0f);
}

float penumbra_receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _1039 = penumbra_shadow_visibility(param);
    return _1039;
}

float penumbra_visibility(float4 light_clip_position)
{
    float2 pixel = 0.0f.xx;
    penumbra_texel_reads = 0.0f;
    float4 param = light_clip_position;
    float3 query = penumbra_clip_to_query(param);
    float3 param_1 = query;
    float2 param_2 = pixel;
    float _1072 = penumbra_receiver_visibility(param_1, param_2);
    return _1072;
}
