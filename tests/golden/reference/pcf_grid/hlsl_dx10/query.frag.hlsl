cbuffer ShadowParams : register(b0)
{
    float4 params_shadow_map_size : packoffset(c0);
    float4 params_light : packoffset(c1);
    float4 params_sampling : packoffset(c2);
    float4 params_screen_size : packoffset(c3);
    float4 params_source_size : packoffset(c4);
    float4 params_minmax_info : packoffset(c5);
};

Texture2D<float> shadow_cmp : register(t2);
SamplerComparisonState _shadow_cmp_sampler : register(s2);
Texture2D<float4> receivers : register(t3);
SamplerState _receivers_sampler : register(s3);

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

float shadow_reference(float z_receiver)
{
    return (z_receiver - params_sampling.y) * params_sampling.z;
}

float shadow_compare_bilinear(float2 uv, float z_receiver)
{
    penumbra_texel_reads += 4.0f;
    float param = z_receiver;
    float reference = shadow_reference(param);
    float3 _67 = float3(uv, reference);
    return shadow_cmp.SampleCmpLevelZero(_shadow_cmp_sampler, _67.xy, _67.z);
}

float shadow_visibility(float3 query)
{
    float sum = 0.0f;
    [loop]
    for (int j = -1; j <= 1; j++)
    {
        [loop]
        for (int i = -1; i <= 1; i++)
        {
            float2 param = query.xy + (float2(float(i), float(j)) * params_shadow_map_size.zw);
            float param_1 = query.z;
            float _112 = shadow_compare_bilinear(param, param_1);
            sum += _112;
        }
    }
    return sum / 9.0f;
}

float receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _142 = shadow_visibility(param);
    return _142;
}

void frag_main()
{
    penumbra_texel_reads = 0.0f;
    float3 query = receivers.SampleLevel(_receivers_sampler, screen_uv, 0.0f).xyz;
    float3 param = query;
    float2 param_1 = floor(screen_uv * params_screen_size.xy);
    float _167 = receiver_visibility(param, param_1);
    float visible = _167;
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
