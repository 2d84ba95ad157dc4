static const float BLUR_WEIGHTS[9] = { 0.02763055078685283660888671875f, 0.0662822425365447998046875f, 0.1238315403461456298828125f, 0.18017382919788360595703125f, 0.20416368544101715087890625f, 0.18017382919788360595703125f, 0.1238315403461456298828125f, 0.0662822425365447998046875f, 0.02763055078685283660888671875f };

// ShadowParams as Direct3D 9 constant registers
uniform float4 params_shadow_map_size : register(c0);
uniform float4 params_light : register(c1);
uniform float4 params_sampling : register(c2);
uniform float4 params_screen_size : register(c3);
uniform float4 params_source_size : register(c4);
uniform float4 params_minmax_info : register(c5);


uniform sampler2D screen_factor : register(s6);

static float4 blurred;
static float2 screen_uv;

struct SPIRV_Cross_Input
{
    float2 screen_uv : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float4 blurred : COLOR0;
};

float blur_factor(float2 screen_uv_1, float2 axis)
{
    float2 pixel = floor(screen_uv_1 * params_screen_size.xy);
    float sum = 0.0f;
    for (int k = -4; k <= 4; k++)
    {
        float2 uv = ((pixel + (axis * float(k))) + 0.5f.xx) * params_screen_size.zw;
        float weight = BLUR_WEIGHTS[k + 4];
        sum += (weight * tex2Dlod(screen_factor, float4(uv, 0.0, 0.0f)).x);
    }
    return sum;
}

void frag_main()
{
    float2 param = screen_uv;
    float2 param_1 = float2(1.0f, 0.0f);
    blurred = float4(blur_factor(param, param_1), 0.0f, 0.0f, 0.0f);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    screen_uv = stage_input.screen_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.blurred = float4(blurred);
    return stage_output;
}
