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

cbuffer ShadowParams : register(b0)
{
    float4 params_shadow_map_size : packoffset(c0);
    float4 params_light : packoffset(c1);
    float4 params_sampling : packoffset(c2);
    float4 params_screen_size : packoffset(c3);
    float4 params_source_size : packoffset(c4);
    float4 params_minmax_info : packoffset(c5);
    float4 params_camera_inverse_0 : packoffset(c6);
    float4 params_camera_inverse_1 : packoffset(c7);
    float4 params_camera_inverse_2 : packoffset(c8);
    float4 params_camera_inverse_3 : packoffset(c9);
    float4 params_light_view_proj_0 : packoffset(c10);
    float4 params_light_view_proj_1 : packoffset(c11);
    float4 params_light_view_proj_2 : packoffset(c12);
    float4 params_light_view_proj_3 : packoffset(c13);
    float4 params_camera_depth_range : packoffset(c14);
};

Texture2D<float4> shadow_depth : register(t1);
SamplerState _shadow_depth_sampler : register(s1);
Texture2D<float4> shadow_minmax : register(t4);
SamplerState _shadow_minmax_sampler : register(s4);
Texture2D<float4> camera_depth : register(t10);
SamplerState _camera_depth_sampler : register(s10);

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

float3 clip_to_query(float4 light_clip_position)
{
    float2 ndc = light_clip_position.xy / light_clip_position.w.xx;
    return float3(0.5f + (0.5f * ndc.x), 0.5f + ((-0.5f) * ndc.y), light_clip_position.w);
}

float shadow_reference(float z_receiver)
{
    return (z_receiver - params_sampling.y) * params_sampling.z;
}

float shadow_compare_point(float2 uv, float z_receiver)
{
    penumbra_texel_reads += 1.0f;
    float param = z_receiver;
    return float(shadow_reference(param) <= shadow_depth.SampleLevel(_shadow_depth_sampler, uv, 0.0f).x);
}

float backprojection_limit(float3 query)
{
    float param = query.z;
    return min(shadow_reference(param), query.z * params_sampling.z);
}

float2 minmax_top_node()
{
    penumbra_texel_reads += 1.0f;
    return shadow_minmax.SampleLevel(_shadow_minmax_sampler, 0.5f.xx, params_minmax_info.x - 1.0f).xy;
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

bool backprojection_start(float3 query, inout float limit, inout float4 window)
{
    float3 param = query;
    limit = backprojection_limit(param);
    float2 _811 = minmax_top_node();
    float map_min = _811.x;
    float3 param_1 = query;
    float param_2 = map_min * params_sampling.w;
    window = backprojection_window(param_1, param_2);
    float4 param_3 = window;
    bool empty = minmax_window_empty(param_3);
    return (map_min < limit) && (!empty);
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
    return shadow_depth.SampleLevel(_shadow_depth_sampler, (texel + 0.5f.xx) * params_shadow_map_size.zw, 0.0f).x;
}

float2 minmax_node(float level, float2 node)
{
    if (level < 0.5f)
    {
        float2 param = node;
        float _252 = shadow_texel(param);
        float depth = _252;
        return float2(depth, depth);
    }
    penumbra_texel_reads += 1.0f;
    float2 uv = (node + 0.5f.xx) * exp2(level - params_minmax_info.x);
    return shadow_minmax.SampleLevel(_shadow_minmax_sampler, uv, level - 1.0f).xy;
}

float2 minmax_cursor_read(MinmaxCursor cursor)
{
    float param = cursor.level;
    float2 param_1 = cursor.node;
    float2 _445 = minmax_node(param, param_1);
    return _445;
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

float backprojection_to_slope()
{
    return params_light.y / params_light.z;
}

float4 backprojection_project(float4 texels, float z, float3 query)
{
    float param = z;
    float param_1 = query.z;
    float scale = backprojection_gain(param, param_1) * backprojection_to_slope();
    float4 corners = float4(texels.xy, texels.zw + 1.0f.xx) * params_shadow_map_size.zwzw;
    return (corners - query.xyxy) * scale;
}

bool backprojection_touches(float4 rect)
{
    float4 _581 = rect * float4(1.0f, 1.0f, -1.0f, -1.0f);
    float4 _584 = params_light.x.xxxx;
    return all(bool4(_581.x <= _584.x, _581.y <= _584.y, _581.z <= _584.z, _581.w <= _584.w));
}

float backprojection_inside(float4 rect)
{
    float2 size = max(min(rect.zw, params_light.x.xx) - max(rect.xy, (-params_light.x).xx), 0.0f.xx);
    return size.x * size.y;
}

float backprojection_add(float area, float4 rect)
{
    float4 param = rect;
    return area + backprojection_inside(param);
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
    float2 _468;
    if (root)
    {
        _468 = cursor.first_root;
    }
    else
    {
        _468 = floor(cursor.node * 0.5f) * 2.0f;
    }
    float2 first_sibling = _468;
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

float backprojection_whole_light_area()
{
    return (4.0f * params_light.x) * params_light.x;
}

bool backprojection_covered(float area)
{
    return area >= backprojection_whole_light_area();
}

float backprojection_walk(float3 query, float4 window, float limit, inout float state)
{
    float visits = 0.0f;
    float4 param = window;
    MinmaxCursor cursor = minmax_begin(param);
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
                bool _692 = !cursor.climbed;
                bool _703;
                if (_692)
                {
                    MinmaxCursor param_1 = cursor;
                    float4 param_2 = window;
                    float4 param_3 = minmax_node_part(param_1, param_2);
                    _703 = !minmax_window_empty(param_3);
                }
                else
                {
                    _703 = _692;
                }
                if (_703)
                {
                    MinmaxCursor param_4 = cursor;
                    float2 _709 = minmax_cursor_read(param_4);
                    float2 range = _709;
                    MinmaxCursor param_5 = cursor;
                    float4 texels = minmax_node_texels(param_5);
                    float4 param_6 = texels;
                    float param_7 = range.x * params_sampling.w;
                    float3 param_8 = query;
                    float4 rect = backprojection_project(param_6, param_7, param_8);
                    float4 param_9 = rect;
                    bool touches = backprojection_touches(param_9);
                    if ((range.x < limit) && touches)
                    {
                        bool _742 = range.y < limit;
                        bool _750;
                        if (_742)
                        {
                            _750 = range.x == range.y;
                        }
                        else
                        {
                            _750 = _742;
                        }
                        bool one_patch = _750;
                        descend = !one_patch;
                        if (one_patch)
                        {
                            float param_10 = state;
                            float4 param_11 = rect;
                            state = backprojection_add(param_10, param_11);
                        }
                    }
                }
                if (descend)
                {
                    MinmaxCursor param_12 = cursor;
                    minmax_descend(param_12);
                    cursor = param_12;
                }
                else
                {
                    MinmaxCursor param_13 = cursor;
                    minmax_next(param_13);
                    cursor = param_13;
                }
                float param_14 = state;
                bool covered = backprojection_covered(param_14);
                cursor.done = (cursor.done || covered) || (visits >= 16384.0f);
            }
        }
    }
    return state;
}

float shadow_visibility(float3 query)
{
    if (!(params_light.x > 0.0f))
    {
        float2 param = query.xy;
        float param_1 = query.z;
        float _845 = shadow_compare_point(param, param_1);
        return _845;
    }
    float3 param_2 = query;
    float param_3;
    float4 param_4;
    bool _853 = backprojection_start(param_2, param_3, param_4);
    float limit = param_3;
    float4 window = param_4;
    if (!_853)
    {
        return 1.0f;
    }
    float3 param_5 = query;
    float4 param_6 = window;
    float param_7 = limit;
    float param_8 = 0.0f;
    float _868 = backprojection_walk(param_5, param_6, param_7, param_8);
    float area = _868;
    return max(0.0f, 1.0f - (area / backprojection_whole_light_area()));
}

float receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _893 = shadow_visibility(param);
    return _893;
}

void frag_main()
{
    penumbra_texel_reads = 0.0f;
    float depth = camera_depth.SampleLevel(_camera_depth_sampler, screen_uv, 0.0f).x;
    float4 clip = float4((2.0f * screen_uv.x) - 1.0f, (screen_uv.y - 0.5f) / (-0.5f), (depth * params_camera_depth_range.x) + params_camera_depth_range.y, 1.0f);
    float4x4 camera_inverse = float4x4(float4(params_camera_inverse_0), float4(params_camera_inverse_1), float4(params_camera_inverse_2), float4(params_camera_inverse_3));
    float4x4 light_view_proj = float4x4(float4(params_light_view_proj_0), float4(params_light_view_proj_1), float4(params_light_view_proj_2), float4(params_light_view_proj_3));
    float4 world = mul(clip, camera_inverse);
    float4 param = mul(world / world.w.xxxx, light_view_proj);
    float3 query = clip_to_query(param);
    if (depth == params_camera_depth_range.z)
    {
        query = float3(0.5f, 0.5f, 0.0f);
    }
    float3 param_1 = query;
    float2 param_2 = floor(screen_uv * params_screen_size.xy);
    float _1044 = receiver_visibility(param_1, param_2);
    float visible = _1044;
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
