static const float BLUR_WEIGHTS[9] = { 0.02763055078685283660888671875f, 0.0662822425365447998046875f, 0.1238315403461456298828125f, 0.18017382919788360595703125f, 0.20416368544101715087890625f, 0.18017382919788360595703125f, 0.1238315403461456298828125f, 0.0662822425365447998046875f, 0.02763055078685283660888671875f };

cbuffer ShadowParams : register(b0)
{
    float4 params_shadow_map_size : packoffset(c0);
    float4 params_light : packoffset(c1);
    float4 params_sampling : packoffset(c2);
    float4 params_screen_size : packoffset(c3);
    float4 params_source_size : packoffset(c4);
    float4 params_minmax_info : packoffset(c5);
};

Texture2D<float4> screen_factor : register(t6);
SamplerState _screen_factor_sampler : register(s6);

static float4 blurred;
static float2 screen_uv;

struct SPIRV_Cross_Input
{
    float2 screen_uv : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float4 blurred : SV_Target0;
};

float blur_factor(float2 screen_uv_1, float2 axis)
{
    float2 pixel = floor(screen_uv_1 * params_screen_size.xy);
    float sum = 0.0f;
    for (int k = -4; k <= 4; k++)
    {
        float2 uv = ((pixel + (axis * float(k))) + 0.5f.xx) * params_screen_size.zw;
        float weight = BLUR_WEIGHTS[k + 4];
        sum += (weight * screen_factor.SampleLevel(_screen_factor_sampler, uv, 0.0f).x);
    }
    return sum;
}

void frag_main()
{
    float2 param = screen_uv;
    float2 param_1 = float2(0.0f, 1.0f);
    blurred = float4(blur_factor(param, param_1), 0.0f, 0.0f, 0.0f);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    screen_uv = stage_input.screen_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.blurred = blurred;
    return stage_output;
}
