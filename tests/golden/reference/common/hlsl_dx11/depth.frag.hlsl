cbuffer ShadowParams : register(b0)
{
    float4 params_shadow_map_size : packoffset(c0);
    float4 params_light : packoffset(c1);
    float4 params_sampling : packoffset(c2);
    float4 params_screen_size : packoffset(c3);
    float4 params_source_size : packoffset(c4);
    float4 params_minmax_info : packoffset(c5);
};


static float gl_FragDepth;
static float light_z;
static float depth_out;

struct SPIRV_Cross_Input
{
    float light_z : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float depth_out : SV_Target0;
    float gl_FragDepth : SV_Depth;
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
    stage_output.depth_out = depth_out;
    return stage_output;
}
