cbuffer ShadowParams : register(b0)
{
    float4 params_shadow_map_size : packoffset(c0);
    float4 params_light : packoffset(c1);
    float4 params_sampling : packoffset(c2);
    float4 params_screen_size : packoffset(c3);
    float4 params_source_size : packoffset(c4);
    float4 params_minmax_info : packoffset(c5);
};


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
    float4 gl_Position : SV_Position;
};

void vert_main()
{
    float far_plane = params_sampling.w;
    float xy_scale = (2.0f * params_light.z) / params_light.y;
    float clip_z = ((position.z - params_light.z) * far_plane) / (far_plane - params_light.z);
    gl_Position = float4(position.xy * xy_scale, clip_z, position.z);
    light_z = position.z;
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
