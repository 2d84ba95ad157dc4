cbuffer penumbra_ShadowParams : register(b0)
{
    float4 penumbra_params_shadow_map_size : packoffset(c0);
    float4 penumbra_params_light : packoffset(c1);
    float4 penumbra_params_sampling : packoffset(c2);
    float4 penumbra_params_screen_size : packoffset(c3);
    float4 penumbra_params_source_size : packoffset(c4);
    float4 penumbra_params_minmax_info : packoffset(c5);
};

Texture2D<float> penumbra_shadow_cmp : register(t2);
SamplerComparisonState _penumbra_shadow_cmp_sampler : register(s2);

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
    float3 _76 = float3(uv, reference);
    return penumbra_shadow_cmp.SampleCmpLevelZero(_penumbra_shadow_cmp_sampler, _76.xy, _76.z);
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
            float _121 = penumbra_shadow_compare_bilinear(param, param_1);
            sum += _121;
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
    float _151 = penumbra_shadow_visibility(param);
    return _151;
}

float penumbra_visibility(float4 light_clip_position)
{
    float2 pixel = 0.0f.xx;
    penumbra_texel_reads = 0.0f;
    float4 param = light_clip_position;
    float3 query = penumbra_clip_to_query(param);
    float3 param_1 = query;
    float2 param_2 = pixel;
    float _188 = penumbra_receiver_visibility(param_1, param_2);
    return _188;
}
