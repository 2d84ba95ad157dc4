static const float2 PCF_DISK[16] = { float2(-0.94201624393463134765625f, -0.39906215667724609375f), float2(0.94558608531951904296875f, -0.768907248973846435546875f), float2(-0.094184100627899169921875f, -0.929388701915740966796875f), float2(0.34495937824249267578125f, 0.29387760162353515625f), float2(-0.91588580608367919921875f, 0.4577143192291259765625f), float2(-0.8154423236846923828125f, -0.87912464141845703125f), float2(-0.38277542591094970703125f, 0.2767684459686279296875f), float2(0.9748439788818359375f, 0.7564837932586669921875f), float2(0.4432332515716552734375f, -0.9751155376434326171875f), float2(0.5374298095703125f, -0.473734200000762939453125f), float2(-0.2649691104888916015625f, -0.418930232524871826171875f), float2(0.79197514057159423828125f, 0.19090187549591064453125f), float2(-0.24188840389251708984375f, 0.997065067291259765625f), float2(-0.8140995502471923828125f, 0.91437590122222900390625f), float2(0.1998412609100341796875f, 0.786413669586181640625f), float2(0.14383161067962646484375f, -0.141007900238037109375f) };

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

Texture2D<float> shadow_cmp : register(t2);
SamplerComparisonState _shadow_cmp_sampler : register(s2);
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
        float _154 = shadow_texel(param);
        float depth = _154;
        return float2(depth, depth);
    }
    penumbra_texel_reads += 1.0f;
    float2 uv = (node + 0.5f.xx) * exp2(level - params_minmax_info.x);
    return shadow_minmax.SampleLevel(_shadow_minmax_sampler, uv, level - 1.0f).xy;
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
                float2 _475 = minmax_node(param_6, param_7);
                float node_min = _475.x;
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
    float3 _118 = float3(uv, reference);
    return shadow_cmp.SampleCmpLevelZero(_shadow_cmp_sampler, _118.xy, _118.z);
}

float PCF_Filter(float2 uv, float zReceiver, float filterRadiusUV)
{
    float sum = 0.0f;
    [loop]
    for (int i = 0; i < 16; i++)
    {
        float2 offset = PCF_DISK[i] * filterRadiusUV;
        float2 param = uv + offset;
        float param_1 = zReceiver;
        float _348 = shadow_compare_bilinear(param, param_1);
        sum += _348;
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
    bool _534 = minmax_find_blocker(param_1, param_2, param_3, param_4);
    zBlocker = param_1;
    if (!_534)
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
    float _568 = PCF_Filter(param_7, param_8, param_9);
    return _568;
}

float receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _588 = shadow_visibility(param);
    return _588;
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
    float _741 = receiver_visibility(param_1, param_2);
    float visible = _741;
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
