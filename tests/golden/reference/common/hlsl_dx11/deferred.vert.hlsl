static float4 gl_Position;
static float2 screen_uv;
static float2 position;

struct SPIRV_Cross_Input
{
    float2 position : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float2 screen_uv : TEXCOORD0;
    float4 gl_Position : SV_Position;
};

void vert_main()
{
    screen_uv = (position * 0.5f) + 0.5f.xx;
    gl_Position = float4(position, 0.0f, 1.0f);
    gl_Position.y = -gl_Position.y;
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    position = stage_input.position;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output.screen_uv = screen_uv;
    return stage_output;
}
