#version 330
// Depth pass in the shape of the emitted glsl330 depth.frag.
#extension GL_GOOGLE_include_directive : require
#include "gl330_params.glsl"

in float light_z;
layout(location = 0) out float depth_out;

void main()
{
    float d = light_z * params.sampling.z;
    depth_out = d;
    gl_FragDepth = d;
}
