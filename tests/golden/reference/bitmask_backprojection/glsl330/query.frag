#version 330
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

struct BackprojectionState
{
    uint rows[8];
    int set;
};

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

struct ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
    vec4 source_size;
    vec4 minmax_info;
};

uniform ShadowParams params;

uniform sampler2D shadow_depth;
uniform sampler2D shadow_minmax;
uniform sampler2D receivers;

in vec2 screen_uv;
layout(location = 0) out vec4 visibility;
float penumbra_texel_reads;

float shadow_reference(float z_receiver)
{
    return (z_receiver - params.sampling.y) * params.sampling.z;
}

float shadow_compare_point(vec2 uv, float z_receiver)
{
    penumbra_texel_reads += 1.0;
    float param = z_receiver;
    return float(shadow_reference(param) <= textureLod(shadow_depth, uv, 0.0).x);
}

float backprojection_limit(vec3 query)
{
    float param = query.z;
    return min(shadow_reference(param), query.z * params.sampling.z);
}

vec2 minmax_top_node()
{
    penumbra_texel_reads += 1.0;
    return textureLod(shadow_minmax, vec2(0.5), params.minmax_info.x - 1.0).xy;
}

vec4 minmax_clip_window(vec2 first, vec2 last)
{
    return vec4(max(first, vec2(0.0)), min(last, params.shadow_map_size.xy - vec2(1.0)));
}

vec4 backprojection_window(vec3 query, float z_min)
{
    float half_width = ((params.light.w * params.light.z) * (query.z - z_min)) / (query.z * z_min);
    vec2 map_size = params.shadow_map_size.xy;
    vec2 param = floor((query.xy - vec2(half_width)) * map_size) - vec2(1.0);
    vec2 param_1 = floor((query.xy + vec2(half_width)) * map_size) + vec2(1.0);
    return minmax_clip_window(param, param_1);
}

bool minmax_window_empty(vec4 window)
{
    return any(greaterThan(window.xy, window.zw));
}

bool backprojection_start(vec3 query, inout float limit, inout vec4 window)
{
    vec3 param = query;
    limit = backprojection_limit(param);
    vec2 _933 = minmax_top_node();
    float map_min = _933.x;
    vec3 param_1 = query;
    float param_2 = map_min * params.sampling.w;
    window = backprojection_window(param_1, param_2);
    vec4 param_3 = window;
    bool empty = minmax_window_empty(param_3);
    return (map_min < limit) && (!empty);
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
        float _377 = shadow_texel(param);
        float depth = _377;
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
    vec2 _569 = minmax_node(param, param_1);
    return _569;
}

vec4 minmax_node_texels(MinmaxCursor cursor)
{
    vec2 first = cursor.node * cursor.span;
    vec2 param = first;
    vec2 param_1 = (first + vec2(cursor.span)) - vec2(1.0);
    return minmax_clip_window(param, param_1);
}

float backprojection_gain(float z, float z_receiver)
{
    return (z * z_receiver) / (z_receiver - z);
}

float backprojection_to_slope()
{
    return params.light.y / params.light.z;
}

vec4 backprojection_project(vec4 texels, float z, vec3 query)
{
    float param = z;
    float param_1 = query.z;
    float scale = backprojection_gain(param, param_1) * backprojection_to_slope();
    vec4 corners = vec4(texels.xy, texels.zw + vec2(1.0)) * params.shadow_map_size.zwzw;
    return (corners - query.xyxy) * scale;
}

bool backprojection_touches(vec4 rect)
{
    return all(lessThanEqual(rect * vec4(1.0, 1.0, -1.0, -1.0), vec4(params.light.x)));
}

int bitmask_popcount(inout uint x)
{
    x -= ((x >> 1u) & 1431655765u);
    x = (x & 858993459u) + ((x >> 2u) & 858993459u);
    x = (x + (x >> 4u)) & 252645135u;
    return int((x * 16843009u) >> 24u);
}

BackprojectionState backprojection_add(inout BackprojectionState state, vec4 rect)
{
    float g = 8.0;
    vec4 t = ((rect + vec4(params.light.x)) * ((g * g) / (2.0 * params.light.x))) - vec4(0.5625, 0.5625, 0.4375, 0.4375);
    int first_row = int(clamp(ceil((t.y - (g - 1.0)) / g), 0.0, g));
    int last_row = int(clamp(floor(t.w / g), -1.0, g - 1.0));
    SPIRV_CROSS_LOOP
    for (int r = first_row; r <= last_row; r++)
    {
        float row = float(r);
        float first = max(ceil((t.x - row) / g), ceil(t.y - (row * g)));
        float last = min(floor((t.z - row) / g), floor(t.w - (row * g)));
        first = clamp(first, 0.0, g);
        last = clamp(last, -1.0, g - 1.0);
        if (first > last)
        {
            continue;
        }
        uint mask = (2u << uint(last)) - (1u << uint(first));
        uint fresh = mask & (~state.rows[r]);
        state.rows[r] |= fresh;
        uint param = fresh;
        int _354 = bitmask_popcount(param);
        state.set += _354;
    }
    return state;
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
    vec2 _592;
    if (root)
    {
        _592 = cursor.first_root;
    }
    else
    {
        _592 = floor(cursor.node * 0.5) * 2.0;
    }
    vec2 first_sibling = _592;
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

bool backprojection_covered(BackprojectionState state)
{
    return state.set >= 64;
}

BackprojectionState backprojection_walk(vec3 query, vec4 window, float limit, inout BackprojectionState state)
{
    float visits = 0.0;
    vec4 param = window;
    MinmaxCursor cursor = minmax_begin(param);
    SPIRV_CROSS_LOOP
    for (int loop_outer = 0; all(bvec2(loop_outer < 1, !cursor.done)); loop_outer++)
    {
        SPIRV_CROSS_LOOP
        for (int loop_middle = 0; all(bvec2(loop_middle < 129, !cursor.done)); loop_middle++)
        {
            SPIRV_CROSS_LOOP
            for (int loop_inner = 0; all(bvec2(loop_inner < 255, !cursor.done)); loop_inner++)
            {
                bool descend = false;
                if (!cursor.climbed)
                {
                    visits += 1.0;
                }
                bool _814 = !cursor.climbed;
                bool _825;
                if (_814)
                {
                    MinmaxCursor param_1 = cursor;
                    vec4 param_2 = window;
                    vec4 param_3 = minmax_node_part(param_1, param_2);
                    _825 = !minmax_window_empty(param_3);
                }
                else
                {
                    _825 = _814;
                }
                if (_825)
                {
                    MinmaxCursor param_4 = cursor;
                    vec2 _831 = minmax_cursor_read(param_4);
                    vec2 range = _831;
                    MinmaxCursor param_5 = cursor;
                    vec4 texels = minmax_node_texels(param_5);
                    vec4 param_6 = texels;
                    float param_7 = range.x * params.sampling.w;
                    vec3 param_8 = query;
                    vec4 rect = backprojection_project(param_6, param_7, param_8);
                    vec4 param_9 = rect;
                    bool touches = backprojection_touches(param_9);
                    if ((range.x < limit) && touches)
                    {
                        bool _864 = range.y < limit;
                        bool _872;
                        if (_864)
                        {
                            _872 = range.x == range.y;
                        }
                        else
                        {
                            _872 = _864;
                        }
                        bool one_patch = _872;
                        descend = !one_patch;
                        if (one_patch)
                        {
                            BackprojectionState param_10 = state;
                            vec4 param_11 = rect;
                            BackprojectionState _882 = backprojection_add(param_10, param_11);
                            state = _882;
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
                BackprojectionState param_14 = state;
                bool covered = backprojection_covered(param_14);
                cursor.done = (cursor.done || covered) || (visits >= 16384.0);
            }
        }
    }
    return state;
}

float shadow_visibility(vec3 query)
{
    if (!(params.light.x > 0.0))
    {
        vec2 param = query.xy;
        float param_1 = query.z;
        float _967 = shadow_compare_point(param, param_1);
        return _967;
    }
    vec3 param_2 = query;
    float param_3;
    vec4 param_4;
    bool _975 = backprojection_start(param_2, param_3, param_4);
    float limit = param_3;
    vec4 window = param_4;
    if (!_975)
    {
        return 1.0;
    }
    BackprojectionState state;
    SPIRV_CROSS_LOOP
    for (int r = 0; r < 8; r++)
    {
        state.rows[r] = 0u;
    }
    state.set = 0;
    vec3 param_5 = query;
    vec4 param_6 = window;
    float param_7 = limit;
    BackprojectionState param_8 = state;
    BackprojectionState _1005 = backprojection_walk(param_5, param_6, param_7, param_8);
    state = _1005;
    return 1.0 - (float(state.set) / 64.0);
}

float receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _1031 = shadow_visibility(param);
    return _1031;
}

void main()
{
    penumbra_texel_reads = 0.0;
    vec3 query = textureLod(receivers, screen_uv, 0.0).xyz;
    vec3 param = query;
    vec2 param_1 = floor(screen_uv * params.screen_size.xy);
    float _1052 = receiver_visibility(param, param_1);
    float visible = _1052;
    visibility = vec4(visible, penumbra_texel_reads, 0.0, 0.0);
}

