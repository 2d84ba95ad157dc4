#version 330
// Depth pass in the shape of the emitted glsl330 depth.vert, without its
// fix-up of clip z to GL's [-w, w], which Vulkan's [0, w] would clip.
#extension GL_GOOGLE_include_directive : require
#include "gl330_params.glsl"

layout(location = 0) in vec3 position;
out float light_z;

void main()
{
    float n = params.light.z;
    float f = params.sampling.w;
    float xy_scale = (2.0 * n) / params.light.y;
    gl_Position = vec4(position.xy * xy_scale, ((position.z - n) * f) / (f - n), position.z);
    light_z = position.z;
}
