#version 450
#if defined(GL_EXT_control_flow_attributes)
#extension GL_EXT_control_flow_attributes : require
#define SPIRV_CROSS_FLATTEN [[flatten]]
#define SPIRV_CROSS_BRANCH [[dont_flatten]]
#define SPIRV_CROSS_UNROLL [[unroll]]
#define SPIRV_CROSS_LOOP [[dont_unroll]]
#else
#define SPIRV_CROSS_FLATTEN
#define SPIRV_CROSS_BRANCH
#define SPIRV_CROSS_UNROLL
#define SPIRV_CROSS_LOOP
#endif

struct MinmaxCursor
{
    vec2 node;
    float level;
    float span;
    vec2 first_root;
    float start;
    bool climbed;
    bool done;
};

layout(binding = 0, std140) uniform ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
    vec4 source_size;
    vec4 minmax_info;
    vec4 camera_inverse_0;
    vec4 camera_inverse_1;
    vec4 camera_inverse_2;
    vec4 camera_inverse_3;
    vec4 light_view_proj_0;
    vec4 light_view_proj_1;
    vec4 light_view_proj_2;
    vec4 light_view_proj_3;
    vec4 camera_depth_range;
} params;

layout(binding = 1) uniform sampler2D shadow_depth;
layout(binding = 4) uniform sampler2D shadow_minmax;
layout(binding = 10) uniform sampler2D camera_depth;

layout(location = 0) in vec2 screen_uv;
layout(location = 0) out vec4 visibility;
float penumbra_texel_reads;

vec3 clip_to_query(vec4 light_clip_position)
{
    vec2 ndc = light_clip_position.xy / vec2(light_clip_position.w);
    return vec3(0.5 + (0.5 * ndc.x), 0.5 + (0.5 * ndc.y), light_clip_position.w);
}

float shadow_reference(float z_receiver)
{
    return (z_receiver - params.sampling.y) * params.sampling.z;
}

vec4 minmax_clip_window(vec2 first, vec2 last)
{
    return vec4(max(first, vec2(0.0)), min(last, params.shadow_map_size.xy - vec2(1.0)));
}

bool minmax_window_empty(vec4 window)
{
    return any(greaterThan(window.xy, window.zw));
}

float minmax_level_spanning(vec4 window, float nodes)
{
    float level = 0.0;
    float inv_span = 1.0;
    SPIRV_CROSS_LOOP
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

MinmaxCursor minmax_begin(vec4 window)
{
    vec4 param = window;
    float param_1 = 2.0;
    MinmaxCursor cursor;
    cursor.level = minmax_level_spanning(param, param_1);
    cursor.span = exp2(cursor.level);
    cursor.start = cursor.level;
    cursor.first_root = floor(window.xy / vec2(cursor.span));
    cursor.node = cursor.first_root;
    cursor.climbed = false;
    cursor.done = false;
    return cursor;
}

vec4 minmax_node_part(MinmaxCursor cursor, vec4 window)
{
    vec2 first = cursor.node * cursor.span;
    return vec4(max(first, window.xy), min((first + vec2(cursor.span)) - vec2(1.0), window.zw));
}

float shadow_texel(vec2 texel)
{
    penumbra_texel_reads += 1.0;
    return textureLod(shadow_depth, (texel + vec2(0.5)) * params.shadow_map_size.zw, 0.0).x;
}

vec2 minmax_node(float level, vec2 node)
{
    if (level < 0.5)
    {
        vec2 param = node;
        float _137 = shadow_texel(param);
        float depth = _137;
        return vec2(depth, depth);
    }
    penumbra_texel_reads += 1.0;
    vec2 uv = (node + vec2(0.5)) * exp2(level - params.minmax_info.x);
    return textureLod(shadow_minmax, uv, level - 1.0).xy;
}

vec2 minmax_cursor_read(MinmaxCursor cursor)
{
    float param = cursor.level;
    vec2 param_1 = cursor.node;
    vec2 _318 = minmax_node(param, param_1);
    return _318;
}

float minmax_texel_count(vec4 part)
{
    return ((part.z - part.x) + 1.0) * ((part.w - part.y) + 1.0);
}

void minmax_descend(inout MinmaxCursor cursor)
{
    cursor.node *= 2.0;
    cursor.level -= 1.0;
    cursor.span *= 0.5;
}

void minmax_next(inout MinmaxCursor cursor)
{
    bool root = cursor.level >= cursor.start;
    vec2 _341;
    if (root)
    {
        _341 = cursor.first_root;
    }
    else
    {
        _341 = floor(cursor.node * 0.5) * 2.0;
    }
    vec2 first_sibling = _341;
    vec2 offset = cursor.node - first_sibling;
    cursor.climbed = false;
    if (offset.x < 0.5)
    {
        cursor.node.x += 1.0;
    }
    else
    {
        if (offset.y < 0.5)
        {
            cursor.node = vec2(first_sibling.x, cursor.node.y + 1.0);
        }
        else
        {
            if (root)
            {
                cursor.done = true;
            }
            else
            {
                cursor.node = floor(cursor.node * 0.5);
                cursor.level += 1.0;
                cursor.span *= 2.0;
                cursor.climbed = true;
            }
        }
    }
}

float minmax_pcf_count(vec2 first, float reference)
{
    float count = 0.0;
    vec2 param = first;
    vec2 param_1 = first + vec2(5.0);
    vec4 window = minmax_clip_window(param, param_1);
    vec4 param_2 = window;
    if (minmax_window_empty(param_2))
    {
        return 0.0;
    }
    vec4 param_3 = window;
    MinmaxCursor cursor = minmax_begin(param_3);
    SPIRV_CROSS_LOOP
    for (int loop_inner = 0; all(bvec2(loop_inner < 149, !cursor.done)); loop_inner++)
    {
        MinmaxCursor param_4 = cursor;
        vec4 param_5 = window;
        vec4 part = minmax_node_part(param_4, param_5);
        bool descend = false;
        bool _445 = !cursor.climbed;
        bool _452;
        if (_445)
        {
            vec4 param_6 = part;
            _452 = !minmax_window_empty(param_6);
        }
        else
        {
            _452 = _445;
        }
        if (_452)
        {
            MinmaxCursor param_7 = cursor;
            vec2 _458 = minmax_cursor_read(param_7);
            vec2 range = _458;
            if (range.y < reference)
            {
                vec4 param_8 = part;
                count += minmax_texel_count(param_8);
            }
            else
            {
                bool _474 = reference > range.x;
                bool _480;
                if (_474)
                {
                    _480 = cursor.level > 0.5;
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

float shadow_visibility(vec3 query)
{
    vec2 first = floor(query.xy * params.shadow_map_size.xy) - vec2(3.0);
    float param = query.z;
    vec2 param_1 = first;
    float param_2 = shadow_reference(param);
    float _517 = minmax_pcf_count(param_1, param_2);
    float count = _517;
    float _520;
    if (count > 0.0)
    {
        _520 = (36.0 - count) * 0.02777777798473834991455078125;
    }
    else
    {
        _520 = 1.0;
    }
    return _520;
}

float receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _549 = shadow_visibility(param);
    return _549;
}

void main()
{
    penumbra_texel_reads = 0.0;
    float depth = textureLod(camera_depth, screen_uv, 0.0).x;
    vec4 clip = vec4((2.0 * screen_uv.x) - 1.0, (screen_uv.y - 0.5) / 0.5, (depth * params.camera_depth_range.x) + params.camera_depth_range.y, 1.0);
    mat4 camera_inverse = mat4(vec4(params.camera_inverse_0), vec4(params.camera_inverse_1), vec4(params.camera_inverse_2), vec4(params.camera_inverse_3));
    mat4 light_view_proj = mat4(vec4(params.light_view_proj_0), vec4(params.light_view_proj_1), vec4(params.light_view_proj_2), vec4(params.light_view_proj_3));
    vec4 world = camera_inverse * clip;
    vec4 param = light_view_proj * (world / vec4(world.w));
    vec3 query = clip_to_query(param);
    if (depth == params.camera_depth_range.z)
    {
        query = vec3(0.5, 0.5, 0.0);
    }
    vec3 param_1 = query;
    vec2 param_2 = floor(screen_uv * params.screen_size.xy);
    float _699 = receiver_visibility(param_1, param_2);
    float visible = _699;
    visibility = vec4(visible, penumbra_texel_reads, 0.0, 0.0);
}

