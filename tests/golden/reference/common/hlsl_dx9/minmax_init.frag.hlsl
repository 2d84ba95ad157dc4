// ShadowParams as Direct3D 9 constant registers
uniform float4 params_shadow_map_size : register(c0);
uniform float4 params_light : register(c1);
uniform float4 params_sampling : register(c2);
uniform float4 params_screen_size : register(c3);
uniform float4 params_source_size : register(c4);
uniform float4 params_minmax_info : register(c5);


uniform sampler2D shadow_depth : register(s1);

static float2 screen_uv;
static float4 minmax;

struct SPIRV_Cross_Input
{
    float2 screen_uv : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float4 minmax : COLOR0;
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
    float d00 = tex2Dlod(shadow_depth, float4(first, 0.0, 0.0f)).x;
    float d10 = tex2Dlod(shadow_depth, float4(first + float2(_step.x, 0.0f), 0.0, 0.0f)).x;
    float d01 = tex2Dlod(shadow_depth, float4(first + float2(0.0f, _step.y), 0.0, 0.0f)).x;
    float d11 = tex2Dlod(shadow_depth, float4(first + _step, 0.0, 0.0f)).x;
    minmax = float4(min(min(d00, d10), min(d01, d11)), max(max(d00, d10), max(d01, d11)), 0.0f, 0.0f);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    screen_uv = stage_input.screen_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.minmax = float4(minmax);
    return stage_output;
}
