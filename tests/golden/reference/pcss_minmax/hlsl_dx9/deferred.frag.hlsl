// ShadowParams as Direct3D 9 constant registers
uniform float4 params_shadow_map_size : register(c0);
uniform float4 params_light : register(c1);
uniform float4 params_sampling : register(c2);
uniform float4 params_screen_size : register(c3);
uniform float4 params_source_size : register(c4);
uniform float4 params_minmax_info : register(c5);
uniform float4 params_camera_inverse_0 : register(c6);
uniform float4 params_camera_inverse_1 : register(c7);
uniform float4 params_camera_inverse_2 : register(c8);
uniform float4 params_camera_inverse_3 : register(c9);
uniform float4 params_light_view_proj_0 : register(c10);
uniform float4 params_light_view_proj_1 : register(c11);
uniform float4 params_light_view_proj_2 : register(c12);
uniform float4 params_light_view_proj_3 : register(c13);
uniform float4 params_camera_depth_range : register(c14);


uniform sampler2D shadow_depth : register(s1);
uniform sampler2D shadow_minmax : register(s4);
uniform sampler2D pcf_disk : register(s8);
uniform sampler2D camera_depth : register(s10);

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
        float _224 = shadow_texel(param);
        float depth = _224;
        return float2(depth, depth);
    }
    penumbra_texel_reads += 1.0f;
    float2 uv = (node + 0.5f.xx) * exp2(level - params_minmax_info.x);
    return tex2Dlod(shadow_minmax, float4(uv, 0.0, level - 1.0f)).xy;
}

float minmax_texel_count(float4 part)
{
    return ((part.z - part.x) + 1.0f) * ((part.w - part.y) + 1.0f);
}

bool minmax_find_blocker(out float zBlocker, float2 uv, float zReceiver, float reference)
{
    zBlocker = zReceiver;
    float searchWidth = (params_light.w * (zReceiver - params_light.z)) / zReceiver;
    float2 map_size = params_shadow_map_size.xy;
    float2 param = floor((uv - searchWidth.xx) * map_size);
    float2 param_1 = floor((uv + searchWidth.xx) * map_size);
    float4 window = minmax_clip_window(param, param_1);
    float4 param_2 = window;
    if (minmax_window_empty(param_2))
    {
        return false;
    }
    float4 param_3 = window;
    float param_4 = 3.0f;
    float level = minmax_level_spanning(param_3, param_4);
    float span = exp2(level);
    float2 first = floor(window.xy / span.xx);
    float depth_sum = 0.0f;
    float texels = 0.0f;
    [loop]
    for (int j = 0; j < 3; j++)
    {
        [loop]
        for (int i = 0; i < 3; i++)
        {
            float2 node = first + float2(float(i), float(j));
            float4 part = float4(max(node * span, window.xy), min(((node * span) + span.xx) - 1.0f.xx, window.zw));
            float4 param_5 = part;
            if (!minmax_window_empty(param_5))
            {
                float param_6 = level;
                float2 param_7 = node;
                float2 _498 = minmax_node(param_6, param_7);
                float node_min = _498.x;
                if (node_min < reference)
                {
                    float4 param_8 = part;
                    float weight = minmax_texel_count(param_8);
                    depth_sum += (node_min * weight);
                    texels += weight;
                }
            }
        }
    }
    if (texels < 0.5f)
    {
        return false;
    }
    zBlocker = (depth_sum / texels) * params_sampling.w;
    return true;
}

float PenumbraSize(float zReceiver, float zBlocker)
{
    return (zReceiver - zBlocker) / zBlocker;
}

float shadow_compare_bilinear(float2 uv, float z_receiver)
{
    penumbra_texel_reads += 4.0f;
    float param = z_receiver;
    float reference = shadow_reference(param);
    float2 texel = (uv * params_shadow_map_size.xy) - 0.5f.xx;
    float2 corner = floor(texel);
    float2 weight = texel - corner;
    float2 uv00 = (corner + 0.5f.xx) * params_shadow_map_size.zw;
    float2 uv11 = uv00 + params_shadow_map_size.zw;
    float lit00 = float(reference <= tex2Dlod(shadow_depth, float4(uv00, 0.0, 0.0f)).x);
    float lit10 = float(reference <= tex2Dlod(shadow_depth, float4(float2(uv11.x, uv00.y), 0.0, 0.0f)).x);
    float lit01 = float(reference <= tex2Dlod(shadow_depth, float4(float2(uv00.x, uv11.y), 0.0, 0.0f)).x);
    float lit11 = float(reference <= tex2Dlod(shadow_depth, float4(uv11, 0.0, 0.0f)).x);
    return lerp(lerp(lit00, lit10, weight.x), lerp(lit01, lit11, weight.x), weight.y);
}

float PCF_Filter(float2 uv, float zReceiver, float filterRadiusUV)
{
    float sum = 0.0f;
    [loop]
    for (int i = 0; i < 16; i++)
    {
        float2 offset = tex2Dlod(pcf_disk, float4(float2((float(i) + 0.5f) / 16.0f, 0.5f), 0.0, 0.0f)).xy * filterRadiusUV;
        float2 param = uv + offset;
        float param_1 = zReceiver;
        float _372 = shadow_compare_bilinear(param, param_1);
        sum += _372;
    }
    return sum / 16.0f;
}

float shadow_visibility(float3 query)
{
    if (!(query.z > params_light.z))
    {
        return 1.0f;
    }
    float zBlocker = 0.0f;
    float param = query.z;
    float2 param_2 = query.xy;
    float param_3 = query.z;
    float param_4 = shadow_reference(param);
    float param_1;
    bool _557 = minmax_find_blocker(param_1, param_2, param_3, param_4);
    zBlocker = param_1;
    if (!_557)
    {
        return 1.0f;
    }
    zBlocker = max(zBlocker, params_light.z);
    float param_5 = query.z;
    float param_6 = zBlocker;
    float filterRadiusUV = ((PenumbraSize(param_5, param_6) * params_light.w) * params_light.z) / query.z;
    float2 param_7 = query.xy;
    float param_8 = query.z;
    float param_9 = filterRadiusUV;
    float _591 = PCF_Filter(param_7, param_8, param_9);
    return _591;
}

float receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _611 = shadow_visibility(param);
    return _611;
}

void frag_main()
{
    penumbra_texel_reads = 0.0f;
    float depth = tex2Dlod(camera_depth, float4(screen_uv, 0.0, 0.0f)).x;
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
    float _764 = receiver_visibility(param_1, param_2);
    float visible = _764;
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
