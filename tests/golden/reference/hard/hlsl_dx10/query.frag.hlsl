cbuffer ShadowParams : register(b0)
{
    float4 params_shadow_map_size : packoffset(c0);
    float4 params_light : packoffset(c1);
    float4 params_sampling : packoffset(c2);
    float4 params_screen_size : packoffset(c3);
    float4 params_source_size : packoffset(c4);
    float4 params_minmax_info : packoffset(c5);
};

Texture2D<float4> shadow_depth : register(t1);
SamplerState _shadow_depth_sampler : register(s1);
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

float shadow_compare_point(float2 uv, float z_receiver)
{
    penumbra_texel_reads += 1.0f;
    float param = z_receiver;
    return float(shadow_reference(param) <= shadow_depth.SampleLevel(_shadow_depth_sampler, uv, 0.0f).x);
}

float shadow_visibility(float3 query)
{
    float2 param = query.xy;
    float param_1 = query.z;
    float _78 = shadow_compare_point(param, param_1);
    return _78;
}

float receiver_visibility(float3 query, float2 pixel)
{
    if (!(query.z > 0.0f))
    {
        return 1.0f;
    }
    float3 param = float3(query.xy, min(query.z, 1152921504606846976.0f));
    float _98 = shadow_visibility(param);
    return _98;
}

void frag_main()
{
    penumbra_texel_reads = 0.0f;
    float3 query = receivers.SampleLevel(_receivers_sampler, screen_uv, 0.0f).xyz;
    float3 param = query;
    float2 param_1 = floor(screen_uv * params_screen_size.xy);
    float _121 = receiver_visibility(param, param_1);
    float visible = _121;
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
