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

float4 minmax_clip_window(float2 first, float2 last)
{
    return float4(max(first, 0.0f.xx), min(last, params_shadow_map_size.xy - 1.0f.xx));
}

bool minmax_window_empty(float4 window)
{
    return any(bool2(window.xy.x > window.zw.x, window.xy.y > window.zw.y));
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
        float _137 = shadow_texel(param);
        float depth = _137;
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
    float2 _318 = minmax_node(param, param_1);
    return _318;
}

float minmax_texel_count(float4 part)
{
    return ((part.z - part.x) + 1.0f) * ((part.w - part.y) + 1.0f);
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
    float2 _341;
    if (root)
    {
        _341 = cursor.first_root;
    }
    else
    {
        _341 = floor(cursor.node * 0.5f) * 2.0f;
    }
    float2 first_sibling = _341;
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

float minmax_pcf_count(float2 first, float reference)
{
    float count = 0.0f;
    float2 param = first;
    float2 param_1 = first + 5.0f.xx;
    float4 window = minmax_clip_window(param, param_1);
    float4 param_2 = window;
    if (minmax_window_empty(param_2))
    {
        return 0.0f;
    }
    float4 param_3 = window;
    MinmaxCursor cursor = minmax_begin(param_3);
    [loop]
    for (int loop_inner = 0; all(bool2(loop_inner < 149, !cursor.done)); loop_inner++)
    {
        MinmaxCursor param_4 = cursor;
        float4 param_5 = window;
        float4 part = minmax_node_part(param_4, param_5);
        bool descend = false;
        bool _445 = !cursor.climbed;
        bool _452;
        if (_445)
        {
            float4 param_6 = part;
            _452 = !minmax_window_empty(param_6);
        }
        else
        {
            _452 = _445;
        }
        if (_452)
        {
            MinmaxCursor param_7 = cursor;
            float2 _458 = minmax_cursor_read(param_7);
            float2 range = _458;
            if (range.y < reference)
            {
                float4 param_8 = part;
                count += minmax_texel_count(param_8);
            }
            else
            {
                bool _474 = reference > range.x;
                bool _480;
                if (_474)
                {
                    _480 = cursor.level > 0.5f;
                }
                else
                {
                    _480 = _474;
                }
                descend = _480;
            }
        }
        if (descend)
        {
            MinmaxCursor param_9 = cursor;
            minmax_descend(param_9);
            cursor = param_9;
        }
        else
        {
            MinmaxCursor param_10 = cursor;
            minmax_next(param_10);
            cursor = param_10;
        }
    }
    return count;
}

float shadow_visibility(float3 query)
{
    float2 first = floor(query.xy * params_shadow_map_size.xy) - 3.0f.xx;
    float param = query.z;
    float2 param_1 = first;
    float param_2 = shadow_reference(param);
    float _517 = minmax_pcf_count(param_1, param_2);
    float count = _517;
    float _520;
    if (count > 0.0f)
    {
        _520 = (36.0f - count) * 0.02777777798473834991455078125f;
    }
    else
    {
        _520 = 1.0f;
    }
    return _520;
}

float receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _549 = shadow_visibility(param);
    return _549;
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
    float _700 = receiver_visibility(param_1, param_2);
    float visible = _700;
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
