uniform sampler2D scene_colour : register(s7);
uniform sampler2D screen_factor : register(s6);

static float2 screen_uv;
static float4 colour;

struct SPIRV_Cross_Input
{
    float2 screen_uv : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float4 colour : COLOR0;
};

void frag_main()
{
    float4 scene = tex2Dlod(scene_colour, float4(screen_uv, 0.0, 0.0f));
    float factor = tex2Dlod(screen_factor, float4(screen_uv, 0.0, 0.0f)).x;
    colour = float4(scene.xyz * factor, scene.w);
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    screen_uv = stage_input.screen_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.colour = float4(colour);
    return stage_output;
}
