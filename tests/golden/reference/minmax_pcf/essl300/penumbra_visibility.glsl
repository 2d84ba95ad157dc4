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

layout(std140) uniform penumbra_ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
    vec4 source_size;
    vec4 minmax_info;
} penumbra_params;

uniform highp sampler2D penumbra_shadow_depth;
uniform highp sampler2D penumbra_shadow_minmax;

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
        float _140 = penumbra_shadow_texel(param);
        float depth = _140;
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
    vec2 _321 = penumbra_minmax_node(param, param_1);
    return _321;
}

float penumbra_minmax_texel_count(vec4 part)
{
    return ((part.z - part.x) + 1.0) * ((part.w - part.y) + 1.0);
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
    vec2 _344;
    if (root)
    {
        _344 = cursor.first_root;
    }
    else
    {
        _344 = floor(cursor.node * 0.5) * 2.0;
    }
    vec2 first_sibling = _344;
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

float penumbra_minmax_pcf_count(vec2 first, float reference)
{
    float count = 0.0;
    vec2 param = first;
    vec2 param_1 = first + vec2(5.0);
    vec4 window = penumbra_minmax_clip_window(param, param_1);
    vec4 param_2 = window;
    if (penumbra_minmax_window_empty(param_2))
    {
        return 0.0;
    }
    vec4 param_3 = window;
    penumbra_MinmaxCursor cursor = penumbra_minmax_begin(param_3);
    for (int loop_inner = 0; all(bvec2(loop_inner < 149, !cursor.done)); loop_inner++)
    {
        penumbra_MinmaxCursor param_4 = cursor;
        vec4 param_5 = window;
        vec4 part = penumbra_minmax_node_part(param_4, param_5);
        bool descend = false;
        bool _448 = !cursor.climbed;
        bool _455;
        if (_448)
        {
            vec4 param_6 = part;
            _455 = !penumbra_minmax_window_empty(param_6);
        }
        else
        {
            _455 = _448;
        }
        if (_455)
        {
            penumbra_MinmaxCursor param_7 = cursor;
            vec2 _461 = penumbra_minmax_cursor_read(param_7);
            vec2 range = _461;
            if (range.y < reference)
            {
                vec4 param_8 = part;
                count += penumbra_minmax_texel_count(param_8);
            }
            else
            {
                bool _477 = reference > range.x;
                bool _483;
                if (_477)
                {
                    _483 = cursor.level > 0.5;
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

float penumbra_shadow_visibility(vec3 query)
{
    vec2 first = floor(query.xy * penumbra_params.shadow_map_size.xy) - vec2(3.0);
    float param = query.z;
    vec2 param_1 = first;
    float param_2 = penumbra_shadow_reference(param);
    float _520 = penumbra_minmax_pcf_count(param_1, param_2);
    float count = _520;
    float _523;
    if (count > 0.0)
    {
        _523 = (36.0 - count) * 0.02777777798473834991455078125;
    }
    else
    {
        _523 = 1.0;
    }
    return _523;
}

float penumbra_receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _552 = penumbra_shadow_visibility(param);
    return _552;
}

float penumbra_visibility(vec4 light_clip_position)
{
    vec2 pixel = vec2(0.0);
    penumbra_texel_reads = 0.0;
    vec4 param = light_clip_position;
    vec3 query = penumbra_clip_to_query(param);
    vec3 param_1 = query;
    vec2 param_2 = pixel;
    float _584 = penumbra_receiver_visibility(param_1, param_2);
    return _584;
}
