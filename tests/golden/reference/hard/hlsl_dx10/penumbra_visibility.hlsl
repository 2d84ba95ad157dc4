cbuffer penumbra_ShadowParams : register(b0)
{
    float4 penumbra_params_shadow_map_size : packoffset(c0);
    float4 penumbra_params_light : packoffset(c1);
    float4 penumbra_params_sampling : packoffset(c2);
    float4 penumbra_params_screen_size : packoffset(c3);
    float4 penumbra_params_source_size : packoffset(c4);
    float4 penumbra_params_minmax_info : packoffset(c5);
};

Texture2D<float4> penumbra_shadow_depth : register(t1);
SamplerState _penumbra_shadow_depth_sampler : register(s1);

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

float penumbra_shadow_compare_point(float2 uv, float z_receiver)
{
    penumbra_texel_reads += 1.0f;
    float param = z_receiver;
    return float(penumbra_shadow_reference(param) <= penumbra_shadow_depth.SampleLevel(_penumbra_shadow_depth_sampler, uv, 0.0f).x);
}

float penumbra_shadow_visibility(float3 query)
{
    float2 param = query.xy;
    float param_1 = query.z;
    float _87 = penumbra_shadow_compare_point(param, param_1);
    return _87;
}

float penumbra_receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _107 = penumbra_shadow_visibility(param);
    return _107;
}

float penumbra_visibility(float4 light_clip_position)
{
    float2 pixel = 0.0f.xx;
    penumbra_texel_reads = 0.0f;
    float4 param = light_clip_position;
    float3 query = penumbra_clip_to_query(param);
    float3 param_1 = query;
    float2 param_2 = pixel;
    float _143 = penumbra_receiver_visibility(param_1, param_2);
    return _143;
}
