// ShadowParams as the hlsl_dx9 target emits it: loose float4 constants,
// which glslang gathers into its global block $Global.
uniform float4 params_shadow_map_size : register(c0);
uniform float4 params_light : register(c1);
uniform float4 params_sampling : register(c2);
uniform float4 params_screen_size : register(c3);
