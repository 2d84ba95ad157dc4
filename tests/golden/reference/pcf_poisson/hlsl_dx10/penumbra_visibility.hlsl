static const float2 penumbra_PCF_DISK[16] = { float2(-0.94201624393463134765625f, -0.39906215667724609375f), float2(0.94558608531951904296875f, -0.768907248973846435546875f), float2(-0.094184100627899169921875f, -0.929388701915740966796875f), float2(0.34495937824249267578125f, 0.29387760162353515625f), float2(-0.91588580608367919921875f, 0.4577143192291259765625f), float2(-0.8154423236846923828125f, -0.87912464141845703125f), float2(-0.38277542591094970703125f, 0.2767684459686279296875f), float2(0.9748439788818359375f, 0.7564837932586669921875f), float2(0.4432332515716552734375f, -0.9751155376434326171875f), float2(0.5374298095703125f, -0.473734200000762939453125f), float2(-0.2649691104888916015625f, -0.418930232524871826171875f), float2(0.79197514057159423828125f, 0.19090187549591064453125f), float2(-0.24188840389251708984375f, 0.997065067291259765625f), float2(-0.8140995502471923828125f, 0.91437590122222900390625f), float2(0.1998412609100341796875f, 0.786413669586181640625f), float2(0.14383161067962646484375f, -0.141007900238037109375f) };

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
    for (int i = 0; i < 16; i++)
    {
        float2 offset = penumbra_PCF_DISK[i] * penumbra_params_sampling.x;
        float2 param = query.xy + offset;
        float param_1 = query.z;
        float _164 = penumbra_shadow_compare_bilinear(param, param_1);
        sum += _164;
    }
    return sum / 16.0f;
}

float penumbra_receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _193 = penumbra_shadow_visibility(param);
    return _193;
}

float penumbra_visibility(float4 light_clip_position)
{
    float2 pixel = 0.0f.xx;
    penumbra_texel_reads = 0.0f;
    float4 param = light_clip_position;
    float3 query = penumbra_clip_to_query(param);
    float3 param_1 = query;
    float2 param_2 = pixel;
    float _229 = penumbra_receiver_visibility(param_1, param_2);
    return _229;
}
