// ShadowParams as Direct3D 9 constant registers
uniform float4 params_shadow_map_size : register(c0);
uniform float4 params_light : register(c1);
uniform float4 params_sampling : register(c2);
uniform float4 params_screen_size : register(c3);
uniform float4 params_source_size : register(c4);
uniform float4 params_minmax_info : register(c5);



static float gl_FragDepth;
static float light_z;
static float depth_out;

struct SPIRV_Cross_Input
{
    float light_z : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float4 depth_out : COLOR0;
    float gl_FragDepth : DEPTH;
};

void frag_main()
{
    float stored = light_z * params_sampling.z;
    depth_out = stored;
    gl_FragDepth = stored;
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    light_z = stage_input.light_z;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.gl_FragDepth = gl_FragDepth;
    stage_output.depth_out = float4(depth_out, 0.0, 0.0, 0.0);
    return stage_output;
}
