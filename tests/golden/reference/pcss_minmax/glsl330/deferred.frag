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

const vec2 PCF_DISK[16] = vec2[](vec2(-0.94201624393463134765625, -0.39906215667724609375), vec2(0.94558608531951904296875, -0.768907248973846435546875), vec2(-0.094184100627899169921875, -0.929388701915740966796875), vec2(0.34495937824249267578125, 0.29387760162353515625), vec2(-0.91588580608367919921875, 0.4577143192291259765625), vec2(-0.8154423236846923828125, -0.87912464141845703125), vec2(-0.38277542591094970703125, 0.2767684459686279296875), vec2(0.9748439788818359375, 0.7564837932586669921875), vec2(0.4432332515716552734375, -0.9751155376434326171875), vec2(0.5374298095703125, -0.473734200000762939453125), vec2(-0.2649691104888916015625, -0.418930232524871826171875), vec2(0.79197514057159423828125, 0.19090187549591064453125), vec2(-0.24188840389251708984375, 0.997065067291259765625), vec2(-0.8140995502471923828125, 0.91437590122222900390625), vec2(0.1998412609100341796875, 0.786413669586181640625), vec2(0.14383161067962646484375, -0.141007900238037109375));

struct ShadowParams
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
};

uniform ShadowParams params;

uniform sampler2DShadow shadow_cmp;
uniform sampler2D shadow_depth;
uniform sampler2D shadow_minmax;
uniform sampler2D camera_depth;

in vec2 screen_uv;
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
        float _154 = shadow_texel(param);
        float depth = _154;
        return vec2(depth, depth);
    }
    penumbra_texel_reads += 1.0;
    vec2 uv = (node + vec2(0.5)) * exp2(level - params.minmax_info.x);
    return textureLod(shadow_minmax, uv, level - 1.0).xy;
}

float minmax_texel_count(vec4 part)
{
    return ((part.z - part.x) + 1.0) * ((part.w - part.y) + 1.0);
}

bool minmax_find_blocker(out float zBlocker, vec2 uv, float zReceiver, float reference)
{
    zBlocker = zReceiver;
    float searchWidth = (params.light.w * (zReceiver - params.light.z)) / zReceiver;
    vec2 map_size = params.shadow_map_size.xy;
    vec2 param = floor((uv - vec2(searchWidth)) * map_size);
    vec2 param_1 = floor((uv + vec2(searchWidth)) * map_size);
    vec4 window = minmax_clip_window(param, param_1);
    vec4 param_2 = window;
    if (minmax_window_empty(param_2))
    {
        return false;
    }
    vec4 param_3 = window;
    float param_4 = 3.0;
    float level = minmax_level_spanning(param_3, param_4);
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
            if (!minmax_window_empty(param_5))
            {
                float param_6 = level;
                vec2 param_7 = node;
                vec2 _475 = minmax_node(param_6, param_7);
                float node_min = _475.x;
                if (node_min < reference)
                {
                    vec4 param_8 = part;
                    float weight = minmax_texel_count(param_8);
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
    zBlocker = (depth_sum / texels) * params.sampling.w;
    return true;
}

float PenumbraSize(float zReceiver, float zBlocker)
{
    return (zReceiver - zBlocker) / zBlocker;
}

float shadow_compare_bilinear(vec2 uv, float z_receiver)
{
    penumbra_texel_reads += 4.0;
    float param = z_receiver;
    float reference = shadow_reference(param);
    vec3 _118 = vec3(uv, reference);
    return textureLod(shadow_cmp, vec3(_118.xy, _118.z), 0.0);
}

float PCF_Filter(vec2 uv, float zReceiver, float filterRadiusUV)
{
    float sum = 0.0;
    for (int i = 0; i < 16; i++)
    {
        vec2 offset = PCF_DISK[i] * filterRadiusUV;
        vec2 param = uv + offset;
        float param_1 = zReceiver;
        float _348 = shadow_compare_bilinear(param, param_1);
        sum += _348;
    }
    return sum / 16.0;
}

float shadow_visibility(vec3 query)
{
    if (!(query.z > params.light.z))
    {
        return 1.0;
    }
    float zBlocker = 0.0;
    float param = query.z;
    vec2 param_2 = query.xy;
    float param_3 = query.z;
    float param_4 = shadow_reference(param);
    float param_1;
    bool _534 = minmax_find_blocker(param_1, param_2, param_3, param_4);
    zBlocker = param_1;
    if (!_534)
    {
        return 1.0;
    }
    zBlocker = max(zBlocker, params.light.z);
    float param_5 = query.z;
    float param_6 = zBlocker;
    float filterRadiusUV = ((PenumbraSize(param_5, param_6) * params.light.w) * params.light.z) / query.z;
    vec2 param_7 = query.xy;
    float param_8 = query.z;
    float param_9 = filterRadiusUV;
    float _568 = PCF_Filter(param_7, param_8, param_9);
    return _568;
}

float receiver_visibility(vec3 query, vec2 pixel)
{
    if (!(query.z > 0.0))
    {
        return 1.0;
    }
    vec3 param = vec3(query.xy, min(query.z, 1152921504606846976.0));
    float _588 = shadow_visibility(param);
    return _588;
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
    float _740 = receiver_visibility(param_1, param_2);
    float visible = _740;
    visibility = vec4(visible, penumbra_texel_reads, 0.0, 0.0);
}

