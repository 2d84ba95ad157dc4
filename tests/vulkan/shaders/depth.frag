#version 450
// Depth pass: normalized depth d = z * depth_scale to output 0 and the depth buffer.
#extension GL_GOOGLE_include_directive : require
#include "params.glsl"

layout(location = 0) in float light_z;
layout(location = 0) out float depth_out;

void main() {
  float d = light_z * params.sampling.z;
  depth_out = d;
  gl_FragDepth = d;
}
