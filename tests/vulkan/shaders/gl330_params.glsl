// ShadowParams as the glsl330 target emits it: a plain uniform struct, which
// glslang (Vulkan relaxed rules) gathers into gl_DefaultUniformBlock.
struct ShadowParams
{
    vec4 shadow_map_size;
    vec4 light;
    vec4 sampling;
    vec4 screen_size;
};

uniform ShadowParams params;
