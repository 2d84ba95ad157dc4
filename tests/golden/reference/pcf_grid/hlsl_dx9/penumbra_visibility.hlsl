// penumbra_ShadowParams as Direct3D 9 constant registers
uniform float4 penumbra_params_shadow_map_size : register(c0);
uniform float4 penumbra_params_light : register(c1);
uniform float4 penumbra_params_sampling : register(c2);
uniform float4 penumbra_params_screen_size : register(c3);
uniform float4 penumbra_params_source_size : register(c4);
uniform float4 penumbra_params_minmax_info : register(c5);

uniform sampler2D penumbra_shadow_depth : register(s1);

static float penumbra_texel_reads;

float3 penumbra_clip_to_query(float4 light_clip_position)
{
    float2 ndc = light_clip_position.xy / light_clip_position.w.xx;
    return float3(0.5f + (0.5f * ndc.x), 0.5f + ((-0.5f) * ndc.y), light_clip_position.w);
}

float penumbra_shadow_reference(float z_receiver)
{
    return (z_receiver - penumbra_params_sampling.y) * penumbra_params_sampling.z;
}

float penumbra_shadow_compare_bilinear(float2 uv, float z_receiver)
{
    penumbra_texel_reads += 4.0f;
    float param = z_receiver;
    float reference = penumbra_shadow_reference(param);
    float2 texel = (uv * penumbra_params_shadow_map_size.xy) - 0.5f.xx;
    float2 corner = floor(texel);
    float2 weight = texel - corner;
    float2 uv00 = (corner + 0.5f.xx) * penumbra_params_shadow_map_size.zw;
    float2 uv11 = uv00 + penumbra_params_shadow_map_size.zw;
    float lit00 = float(reference <= tex2Dlod(penumbra_shadow_depth, float4(uv00, 0.0, 0.0f)).x);
    float lit10 = float(reference <= tex2Dlod(penumbra_shadow_depth, float4(float2(uv11.x, uv00.y), 0.0, 0.0f)).x);
    float lit01 = float(reference <= tex2Dlod(penumbra_shadow_depth, float4(float2(uv00.x, uv11.y), 0.0, 0.0f)).x);
    float lit11 = float(reference <= tex2Dlod(penumbra_shadow_depth, float4(uv11, 0.0, 0.0f)).x);
    return lerp(lerp(lit00, lit10, weight.x), lerp(lit01, lit11, weight.x), weight.y);
}

float penumbra_shadow_visibility(float3 query)
{
    float sum = 0.0f;
    [loop]
    for (int j = -1; j <= 1; j++)
    {
        [loop]
        for (int i = -1; i <= 1; i++)
        {
            float2 param = query.xy + (float2(float(i), float(j)) * penumbra_params_shadow_map_size.zw);
            float param_1 = query.z;
            float _198 = penumbra_shadow_compare_bilinear(param, param_1);
            sum += _198;
        }
    }
    return sum / 9.0f;
}

float penumbra_receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _227 = penumbra_shadow_visibility(param);
    return _227;
}

float penumbra_visibility(float4 light_clip_position)
{
    float2 pixel = 0.0f.xx;
    penumbra_texel_reads = 0.0f;
    float4 param = light_clip_position;
    float3 query = penumbra_clip_to_query(param);
    float3 param_1 = query;
    float2 param_2 = pixel;
    float _262 = penumbra_receiver_visibility(param_1, param_2);
    return _262;
}
