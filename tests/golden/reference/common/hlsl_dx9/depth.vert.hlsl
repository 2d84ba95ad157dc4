// ShadowParams as Direct3D 9 constant registers
uniform float4 params_shadow_map_size : register(c0);
uniform float4 params_light : register(c1);
uniform float4 params_sampling : register(c2);
uniform float4 params_screen_size : register(c3);
uniform float4 params_source_size : register(c4);
uniform float4 params_minmax_info : register(c5);


uniform float4 gl_HalfPixel : register(c6);

static float4 gl_Position;
static float3 position;
static float light_z;

struct SPIRV_Cross_Input
{
    float3 position : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float light_z : TEXCOORD0;
    float4 gl_Position : POSITION;
};

void vert_main()
{
    float far_plane = params_sampling.w;
    float xy_scale = (2.0f * params_light.z) / params_light.y;
    float clip_z = ((position.z - params_light.z) * far_plane) / (far_plane - params_light.z);
    gl_Position = float4(position.xy * xy_scale, clip_z, position.z);
    light_z = position.z;
    gl_Position.x = gl_Position.x - gl_HalfPixel.x * gl_Position.w;
    gl_Position.y = gl_Position.y - gl_HalfPixel.y * gl_Position.w;
    gl_Position.y = -gl_Position.y;
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    position = stage_input.position;
    vert_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_Position = gl_Position;
    stage_output.light_z = light_z;
    return stage_output;
}
