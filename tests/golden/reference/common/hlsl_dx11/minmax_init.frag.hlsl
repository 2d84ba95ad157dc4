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

static float2 screen_uv;
static float4 minmax;

struct SPIRV_Cross_Input
{
    float2 screen_uv : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float4 minmax : SV_Target0;
};

float2 minmax_source_uv(float2 screen_uv_1)
{
    float2 texel = floor(screen_uv_1 * params_screen_size.xy);
    return ((texel * 2.0f) + 0.5f.xx) * params_source_size.zw;
}

void frag_main()
{
    float2 param = screen_uv;
    float2 first = minmax_source_uv(param);
    float2 _step = params_source_size.zw;
    float d00 = shadow_depth.SampleLevel(_shadow_depth_sampler, first, 0.0f).x;
    float d10 = shadow_depth.SampleLevel(_shadow_depth_sampler, first + float2(_step.x, 0.0f), 0.0f).x;
    float d01 = shadow_depth.SampleLevel(_shadow_depth_sampler, first + float2(0.0f, _step.y), 0.0f).x;
    float d11 = shadow_depth.SampleLevel(_shadow_depth_sampler, first + _step, 0.0f).x;
    minmax = float4(min(min(d00, d10), min(d01, d11)), max(max(d00, d10), max(d01, d11)), 0.0f, 0.0f);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    screen_uv = stage_input.screen_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.minmax = minmax;
    return stage_output;
}
