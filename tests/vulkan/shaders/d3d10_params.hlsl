// ShadowParams as the hlsl_dx10 target emits it: a cbuffer whose members
// SPIRV-Cross flattened to params_<member>.
cbuffer ShadowParams : register(b0)
{
    float4 params_shadow_map_size : packoffset(c0);
    float4 params_light : packoffset(c1);
    float4 params_sampling : packoffset(c2);
    float4 params_screen_size : packoffset(c3);
};
