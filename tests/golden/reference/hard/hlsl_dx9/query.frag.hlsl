// ShadowParams as Direct3D 9 constant registers
uniform float4 params_shadow_map_size : register(c0);
uniform float4 params_light : register(c1);
uniform float4 params_sampling : register(c2);
uniform float4 params_screen_size : register(c3);


uniform sampler2D shadow_depth;
uniform sampler2D receivers;

static float2 screen_uv;
static float4 visibility;

struct SPIRV_Cross_Input
{
    float2 screen_uv : TEXCOORD0;
};

struct SPIRV_Cross_Output
{
    float4 visibility : COLOR0;
};

float shadow_reference(float z_receiver)
{
    return (z_receiver - params_sampling.y) * params_sampling.z;
}

float shadow_compare_point(float2 uv, float z_receiver)
{
    float param = z_receiver;
    return float(shadow_reference(param) <= tex2Dlod(shadow_depth, float4(uv, 0.0, 0.0f)).x);
}

float shadow_visibility(float3 query)
{
    float2 param = query.xy;
    float param_1 = query.z;
    return shadow_compare_point(param, param_1);
}

void frag_main()
{
    float3 query = tex2Dlod(receivers, float4(screen_uv, 0.0, 0.0f)).xyz;
    float3 param = query;
    visibility = shadow_visibility(param).xxxx;
}

SPIRV_Cross_Output main(SPIRV_Cross_Input stage_input)
{
    screen_uv = stage_input.screen_uv;
    frag_main();
    SPIRV_Cross_Output stage_output;
    stage_output.visibility = float4(visibility);
    return stage_output;
}
