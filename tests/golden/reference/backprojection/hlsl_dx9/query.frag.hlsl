struct MinmaxCursor
{
    float2 node;
    float level;
    float span;
    float2 first_root;
    float start;
    bool climbed;
    bool done;
};

// ShadowParams as Direct3D 9 constant registers
uniform float4 params_shadow_map_size : register(c0);
uniform float4 params_light : register(c1);
uniform float4 params_sampling : register(c2);
uniform float4 params_screen_size : register(c3);
uniform float4 params_source_size : register(c4);
uniform float4 params_minmax_info : register(c5);


uniform sampler2D shadow_depth : register(s1);
uniform sampler2D shadow_minmax : register(s4);
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

float shadow_reference(float z_receiver)
{
    return (z_receiver - params_sampling.y) * params_sampling.z;
}

float shadow_compare_point(float2 uv, float z_receiver)
{
    penumbra_texel_reads += 1.0f;
    float param = z_receiver;
    return float(shadow_reference(param) <= tex2Dlod(shadow_depth, float4(uv, 0.0, 0.0f)).x);
}

float2 minmax_top_node()
{
    penumbra_texel_reads += 1.0f;
    return tex2Dlod(shadow_minmax, float4(0.5f.xx, 0.0, params_minmax_info.x - 1.0f)).xy;
}

float4 minmax_clip_window(float2 first, float2 last)
{
    return float4(max(first, 0.0f.xx), min(last, params_shadow_map_size.xy - 1.0f.xx));
}

float4 backprojection_window(float3 query, float z_min)
{
    float half_width = ((params_light.w * params_light.z) * (query.z - z_min)) / (query.z * z_min);
    float2 map_size = params_shadow_map_size.xy;
    float2 param = floor((query.xy - half_width.xx) * map_size) - 1.0f.xx;
    float2 param_1 = floor((query.xy + half_width.xx) * map_size) + 1.0f.xx;
    return minmax_clip_window(param, param_1);
}

bool minmax_window_empty(float4 window)
{
    return any(bool2(window.xy.x > window.zw.x, window.xy.y > window.zw.y));
}

float2 backprojection_slope(float2 uv)
{
    return (uv - 0.5f.xx) * (params_light.y / params_light.z);
}

float backprojection_whole_light_area()
{
    return (4.0f * params_light.x) * params_light.x;
}

float minmax_level_spanning(float4 window, float nodes)
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

MinmaxCursor minmax_begin(float4 window)
{
    float4 param = window;
    float param_1 = 2.0f;
    MinmaxCursor cursor;
    cursor.level = minmax_level_spanning(param, param_1);
    cursor.span = exp2(cursor.level);
    cursor.start = cursor.level;
    cursor.first_root = floor(window.xy / cursor.span.xx);
    cursor.node = cursor.first_root;
    cursor.climbed = false;
    cursor.done = false;
    return cursor;
}

float4 minmax_node_part(MinmaxCursor cursor, float4 window)
{
    float2 first = cursor.node * cursor.span;
    return float4(max(first, window.xy), min((first + cursor.span.xx) - 1.0f.xx, window.zw));
}

float shadow_texel(float2 texel)
{
    penumbra_texel_reads += 1.0f;
    return tex2Dlod(shadow_depth, float4((texel + 0.5f.xx) * params_shadow_map_size.zw, 0.0, 0.0f)).x;
}

float2 minmax_node(float level, float2 node)
{
    if (level < 0.5f)
    {
        float2 param = node;
        float _188 = shadow_texel(param);
        float depth = _188;
        return float2(depth, depth);
    }
    penumbra_texel_reads += 1.0f;
    float2 uv = (node + 0.5f.xx) * exp2(level - params_minmax_info.x);
    return tex2Dlod(shadow_minmax, float4(uv, 0.0, level - 1.0f)).xy;
}

float2 minmax_cursor_read(MinmaxCursor cursor)
{
    float param = cursor.level;
    float2 param_1 = cursor.node;
    float2 _383 = minmax_node(param, param_1);
    return _383;
}

float4 minmax_node_texels(MinmaxCursor cursor)
{
    float2 first = cursor.node * cursor.span;
    float2 param = first;
    float2 param_1 = (first + cursor.span.xx) - 1.0f.xx;
    return minmax_clip_window(param, param_1);
}

float backprojection_gain(float z, float z_receiver)
{
    return (z * z_receiver) / (z_receiver - z);
}

float4 backprojection_project(float4 texels, float z, float3 query, float2 receiver_slope)
{
    float param = z;
    float param_1 = query.z;
    float gain = backprojection_gain(param, param_1);
    float2 param_2 = texels.xy * params_shadow_map_size.zw;
    float2 param_3 = (texels.zw + 1.0f.xx) * params_shadow_map_size.zw;
    return float4((backprojection_slope(param_2) - receiver_slope) * gain, (backprojection_slope(param_3) - receiver_slope) * gain);
}

bool backprojection_can_touch(float4 texels, float z_min, float3 query, float2 receiver_slope)
{
    float4 param = texels;
    float param_1 = z_min;
    float3 param_2 = query;
    float2 param_3 = receiver_slope;
    float4 rect = backprojection_project(param, param_1, param_2, param_3);
    float2 _573 = params_light.x.xx;
    bool _575 = all(bool2(rect.xy.x <= _573.x, rect.xy.y <= _573.y));
    bool _586;
    if (_575)
    {
        float2 _583 = (-params_light.x).xx;
        _586 = all(bool2(rect.zw.x >= _583.x, rect.zw.y >= _583.y));
    }
    else
    {
        _586 = _575;
    }
    return _586;
}

float backprojection_light_area(float4 rect)
{
    float2 size = max(min(rect.zw, params_light.x.xx) - max(rect.xy, (-params_light.x).xx), 0.0f.xx);
    return size.x * size.y;
}

void minmax_descend(inout MinmaxCursor cursor)
{
    cursor.node *= 2.0f;
    cursor.level -= 1.0f;
    cursor.span *= 0.5f;
}

void minmax_next(inout MinmaxCursor cursor)
{
    bool root = cursor.level >= cursor.start;
    float2 _406;
    if (root)
    {
        _406 = cursor.first_root;
    }
    else
    {
        _406 = floor(cursor.node * 0.5f) * 2.0f;
    }
    float2 first_sibling = _406;
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

float backprojection_area(float3 query, float4 window, float limit)
{
    float2 param = query.xy;
    float2 receiver_slope = backprojection_slope(param);
    float light_area = backprojection_whole_light_area();
    float area = 0.0f;
    float visits = 0.0f;
    float4 param_1 = window;
    MinmaxCursor cursor = minmax_begin(param_1);
    [loop]
    for (int loop_outer = 0; all(bool2(loop_outer < 1, !cursor.done)); loop_outer++)
    {
        [loop]
        for (int loop_middle = 0; all(bool2(loop_middle < 1, !cursor.done)); loop_middle++)
        {
            [loop]
            for (int loop_inner = 0; all(bool2(loop_inner < 224, !cursor.done)); loop_inner++)
            {
                bool descend = false;
                if (!cursor.climbed)
                {
                    visits += 1.0f;
                }
                bool _698 = !cursor.climbed;
                bool _709;
                if (_698)
                {
                    MinmaxCursor param_2 = cursor;
                    float4 param_3 = window;
                    float4 param_4 = minmax_node_part(param_2, param_3);
                    _709 = !minmax_window_empty(param_4);
                }
                else
                {
                    _709 = _698;
                }
                if (_709)
                {
                    MinmaxCursor param_5 = cursor;
                    float2 _715 = minmax_cursor_read(param_5);
                    float2 range = _715;
                    MinmaxCursor param_6 = cursor;
                    float4 texels = minmax_node_texels(param_6);
                    float z_min = range.x * params_sampling.w;
                    bool _729 = range.x < limit;
                    bool _741;
                    if (_729)
                    {
                        float4 param_7 = texels;
                        float param_8 = z_min;
                        float3 param_9 = query;
                        float2 param_10 = receiver_slope;
                        _741 = backprojection_can_touch(param_7, param_8, param_9, param_10);
                    }
                    else
                    {
                        _741 = _729;
                    }
                    if (_741)
                    {
                        bool _747 = range.y < limit;
                        bool _755;
                        if (_747)
                        {
                            _755 = range.x == range.y;
                        }
                        else
                        {
                            _755 = _747;
                        }
                        if (_755)
                        {
                            float4 param_11 = texels;
                            float param_12 = z_min;
                            float3 param_13 = query;
                            float2 param_14 = receiver_slope;
                            float4 param_15 = backprojection_project(param_11, param_12, param_13, param_14);
                            area += backprojection_light_area(param_15);
                        }
                        else
                        {
                            descend = cursor.level > 0.5f;
                        }
                    }
                }
                if (descend)
                {
                    MinmaxCursor param_16 = cursor;
                    minmax_descend(param_16);
                    cursor = param_16;
                }
                else
                {
                    MinmaxCursor param_17 = cursor;
                    minmax_next(param_17);
                    cursor = param_17;
                }
                cursor.done = (cursor.done || (area >= light_area)) || (visits >= 16384.0f);
            }
        }
    }
    return area;
}

float shadow_visibility(float3 query)
{
    if (!(params_light.x > 0.0f))
    {
        float2 param = query.xy;
        float param_1 = query.z;
        float _819 = shadow_compare_point(param, param_1);
        return _819;
    }
    float param_2 = query.z;
    float limit = min(shadow_reference(param_2), query.z * params_sampling.z);
    float2 _833 = minmax_top_node();
    float map_min = _833.x;
    if (!(map_min < limit))
    {
        return 1.0f;
    }
    float3 param_3 = query;
    float param_4 = map_min * params_sampling.w;
    float4 window = backprojection_window(param_3, param_4);
    float4 param_5 = window;
    if (minmax_window_empty(param_5))
    {
        return 1.0f;
    }
    float3 param_6 = query;
    float4 param_7 = window;
    float param_8 = limit;
    float _863 = backprojection_area(param_6, param_7, param_8);
    return max(0.0f, 1.0f - (_863 / backprojection_whole_light_area()));
}

float receiver_visibility(float3 query)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _887 = shadow_visibility(param);
    return _887;
}

void frag_main()
{
    penumbra_texel_reads = 0.0f;
    float3 query = tex2Dlod(receivers, float4(screen_uv, 0.0, 0.0f)).xyz;
    float3 param = query;
    float _901 = receiver_visibility(param);
    float visible = _901;
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
