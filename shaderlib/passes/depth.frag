#version 450
// The NVIDIA PCSS whitepaper's step 1: write linear light-view z (normalized by the
// power-of-two DEPTH_SCALE, so exact) to the R32F target and to the depth
// buffer, so one pass fills an R32F map (Direct3D 9) or a depth map.
#extension GL_GOOGLE_include_directive : require
#include "variant.glsl"
#include "common/params.glsl"

layout(location = 0) in float light_z;
layout(location = 0) out float depth_out;

void main() {
  float normalized = light_z * DEPTH_SCALE;
  depth_out = normalized;
  gl_FragDepth = normalized;
}
