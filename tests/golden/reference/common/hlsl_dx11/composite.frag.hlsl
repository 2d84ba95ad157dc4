Texture2D<float4> scene_colour : register(t7);
SamplerState _scene_colour_sampler : register(s7);
Texture2D<float4> screen_factor : register(t6);
SamplerState _screen_factor_sampler : register(s6);

static float2 screen_uv;
static float4 colour;

struct SPIRV_Cross_Input
{
    float2 screen_uv : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float4 colour : SV_Target0;
};

void frag_main()
{
    float4 scene = scene_colour.SampleLevel(_scene_colour_sampler, screen_uv, 0.0f);
    float factor = screen_factor.SampleLevel(_screen_factor_sampler, screen_uv, 0.0f).x;
    colour = float4(scene.xyz * factor, scene.w);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    screen_uv = stage_input.screen_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.colour = colour;
    return stage_output;
}
