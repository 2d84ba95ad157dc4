struct penumbra_MinmaxCursor
{
    vec2 node;
    float level;
    float span;
    vec2 first_root;
    float start;
    bool climbed;
    bool done;
};

layout(binding = 0, std140) uniform penumbra_ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
    vec4 source_size;
    vec4 minmax_info;
} penumbra_params;

layout(binding = 1) uniform sampler2D penumbra_shadow_depth;
layout(binding = 4) uniform sampler2D penumbra_shadow_minmax;

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

float penumbra_shadow_compare_point(vec2 uv, float z_receiver)
{
    penumbra_texel_reads += 1.0;
    float param = z_receiver;
    return float(penumbra_shadow_reference(param) <= textureLod(penumbra_shadow_depth, uv, 0.0).x);
}

float penumbra_backprojection_limit(vec3 query)
{
    float param = query.z;
    return min(penumbra_shadow_reference(param), query.z * penumbra_params.sampling.z);
}

vec2 penumbra_minmax_top_node()
{
    penumbra_texel_reads += 1.0;
    return textureLod(penumbra_shadow_minmax, vec2(0.5), penumbra_params.minmax_info.x - 1.0).xy;
}

vec4 penumbra_minmax_clip_window(vec2 first, vec2 last)
{
    return vec4(max(first, vec2(0.0)), min(last, penumbra_params.shadow_map_size.xy - vec2(1.0)));
}

vec4 penumbra_backprojection_window(vec3 query, float z_min)
{
    float half_width = ((penumbra_params.light.w * penumbra_params.light.z) * (query.z - z_min)) / (query.z * z_min);
    vec2 map_size = penumbra_params.shadow_map_size.xy;
    vec2 param = floor((query.xy - vec2(half_width)) * map_size) - vec2(1.0);
    vec2 param_1 = floor((query.xy + vec2(half_width)) * map_size) + vec2(1.0);
    return penumbra_minmax_clip_window(param, param_1);
}

bool penumbra_minmax_window_empty(vec4 window)
{
    return any(greaterThan(window.xy, window.zw));
}

bool penumbra_backprojection_start(vec3 query, inout float limit, inout vec4 window)
{
    vec3 param = query;
    limit = penumbra_backprojection_limit(param);
    vec2 _814 = penumbra_minmax_top_node();
    float map_min = _814.x;
    vec3 param_1 = query;
    float param_2 = map_min * penumbra_params.sampling.w;
    window = penumbra_backprojection_window(param_1, param_2);
    vec4 param_3 = window;
    bool empty = penumbra_minmax_window_empty(param_3);
    return (map_min < limit) && (!empty);
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

penumbra_MinmaxCursor penumbra_minmax_begin(vec4 window)
{
    vec4 param = window;
    float param_1 = 2.0;
    penumbra_MinmaxCursor cursor;
    cursor.level = penumbra_minmax_level_spanning(param, param_1);
    cursor.span = exp2(cursor.level);
    cursor.start = cursor.level;
    cursor.first_root = floor(window.xy / vec2(cursor.span));
    cursor.node = cursor.first_root;
    cursor.climbed = false;
    cursor.done = false;
    return cursor;
}

vec4 penumbra_minmax_node_part(penumbra_MinmaxCursor cursor, vec4 window)
{
    vec2 first = cursor.node * cursor.span;
    return vec4(max(first, window.xy), min((first + vec2(cursor.span)) - vec2(1.0), window.zw));
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
        float _255 = penumbra_shadow_texel(param);
        float depth = _255;
        return vec2(depth, depth);
    }
    penumbra_texel_reads += 1.0;
    vec2 uv = (node + vec2(0.5)) * exp2(level - penumbra_params.minmax_info.x);
    return textureLod(penumbra_shadow_minmax, uv, level - 1.0).xy;
}

vec2 penumbra_minmax_cursor_read(penumbra_MinmaxCursor cursor)
{
    float param = cursor.level;
    vec2 param_1 = cursor.node;
    vec2 _448 = penumbra_minmax_node(param, param_1);
    return _448;
}

vec4 penumbra_minmax_node_texels(penumbra_MinmaxCursor cursor)
{
    vec2 first = cursor.node * cursor.span;
    vec2 param = first;
    vec2 param_1 = (first + vec2(cursor.span)) - vec2(1.0);
    return penumbra_minmax_clip_window(param, param_1);
}

float penumbra_backprojection_gain(float z, float z_receiver)
{
    return (z * z_receiver) / (z_receiver - z);
}

float penumbra_backprojection_to_slope()
{
    return penumbra_params.light.y / penumbra_params.light.z;
}

vec4 penumbra_backprojection_project(vec4 texels, float z, vec3 query)
{
    float param = z;
    float param_1 = query.z;
    float scale = penumbra_backprojection_gain(param, param_1) * penumbra_backprojection_to_slope();
    vec4 corners = vec4(texels.xy, texels.zw + vec2(1.0)) * penumbra_params.shadow_map_size.zwzw;
    return (corners - query.xyxy) * scale;
}

bool penumbra_backprojection_touches(vec4 rect)
{
    return all(lessThanEqual(rect * vec4(1.0, 1.0, -1.0, -1.0), vec4(penumbra_params.light.x)));
}

float penumbra_backprojection_inside(vec4 rect)
{
    vec2 size = max(min(rect.zw, vec2(penumbra_params.light.x)) - max(rect.xy, vec2(-penumbra_params.light.x)), vec2(0.0));
    return size.x * size.y;
}

float penumbra_backprojection_add(float area, vec4 rect)
{
    vec4 param = rect;
    return area + penumbra_backprojection_inside(param);
}

void penumbra_minmax_descend(inout penumbra_MinmaxCursor cursor)
{
    cursor.node *= 2.0;
    cursor.level -= 1.0;
    cursor.span *= 0.5;
}

void penumbra_minmax_next(inout penumbra_MinmaxCursor cursor)
{
    bool root = cursor.level >= cursor.start;
    vec2 _471;
    if (root)
    {
        _471 = cursor.first_root;
    }
    else
    {
        _471 = floor(cursor.node * 0.5) * 2.0;
    }
    vec2 first_sibling = _471;
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

float penumbra_backprojection_whole_light_area()
{
    return (4.0 * penumbra_params.light.x) * penumbra_params.light.x;
}

bool penumbra_backprojection_covered(float area)
{
    return area >= penumbra_backprojection_whole_light_area();
}

float penumbra_backprojection_walk(vec3 query, vec4 window, float limit, inout float state)
{
    float visits = 0.0;
    vec4 param = window;
    penumbra_MinmaxCursor cursor = penumbra_minmax_begin(param);
    for (int loop_outer = 0; all(bvec2(loop_outer < 1, !cursor.done)); loop_outer++)
    {
        for (int loop_middle = 0; all(bvec2(loop_middle < 129, !cursor.done)); loop_middle++)
        {
            for (int loop_inner = 0; all(bvec2(loop_inner < 255, !cursor.done)); loop_inner++)
            {
                bool descend = false;
                if (!cursor.climbed)
                {
                    visits += 1.0;
                }
                bool _695 = !cursor.climbed;
                bool _706;
                if (_695)
                {
                    penumbra_MinmaxCursor param_1 = cursor;
                    vec4 param_2 = window;
                    vec4 param_3 = penumbra_minmax_node_part(param_1, param_2);
                    _706 = !penumbra_minmax_window_empty(param_3);
                }
                else
                {
                    _706 = _695;
                }
                if (_706)
                {
                    penumbra_MinmaxCursor param_4 = cursor;
                    vec2 _712 = penumbra_minmax_cursor_read(param_4);
                    vec2 range = _712;
                    penumbra_MinmaxCursor param_5 = cursor;
                    vec4 texels = penumbra_minmax_node_texels(param_5);
                    vec4 param_6 = texels;
                    float param_7 = range.x * penumbra_params.sampling.w;
                    vec3 param_8 = query;
                    vec4 rect = penumbra_backprojection_project(param_6, param_7, param_8);
                    vec4 param_9 = rect;
                    bool touches = penumbra_backprojection_touches(param_9);
                    if ((range.x < limit) && touches)
                    {
                        bool _745 = range.y < limit;
                        bool _753;
                        if (_745)
                        {
                            _753 = range.x == range.y;
                        }
                        else
                        {
                            _753 = _745;
                        }
                        bool one_patch = _753;
                        descend = !one_patch;
                        if (one_patch)
                        {
                            float param_10 = state;
                            vec4 param_11 = rect;
                            state = penumbra_backprojection_add(param_10, param_11);
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
                float param_14 = state;
                bool covered = penumbra_backprojection_covered(param_14);
                cursor.done = (cursor.done || covered) || (visits >= 16384.0);
            }
        }
    }
    return state;
}

float penumbra_shadow_visibility(vec3 query)
{
    if (!(penumbra_params.light.x > 0.0))
    {
        vec2 param = query.xy;
        float param_1 = query.z;
        float _848 = penumbra_shadow_compare_point(param, param_1);
        return _848;
    }
    vec3 param_2 = query;
    float param_3;
    vec4 param_4;
    bool _856 = penumbra_backprojection_start(param_2, param_3, param_4);
    float limit = param_3;
    vec4 window = param_4;
    if (!_856)
    {
        return 1.0;
    }
    vec3 param_5 = query;
    vec4 param_6 = window;
    float param_7 = limit;
    float param_8 = 0.0;
    float _871 = penumbra_backprojection_walk(param_5, param_6, param_7, param_8);
    float area = _871;
    return max(0.0, 1.0 - (area / penumbra_backprojection_whole_light_area()));
}

float penumbra_receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _896 = penumbra_shadow_visibility(param);
    return _896;
}

float penumbra_visibility(vec4 light_clip_position)
{
    vec2 pixel = vec2(0.0);
    penumbra_texel_reads = 0.0;
    vec4 param = light_clip_position;
    vec3 query = penumbra_clip_to_query(param);
    vec3 param_1 = query;
    vec2 param_2 = pixel;
    float _928 = penumbra_receiver_visibility(param_1, param_2);
    return _928;
}
