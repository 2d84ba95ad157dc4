#version 450
// Depth pass: light-view position to clip space, docs/shader-interface.md's projection
// u = 0.5 + (x n / z) / Fw, with clip z spanning [n, 1/depth_scale].
// FLIP_Y negates clip y at the end, as Direct3D shaders do.
#extension GL_GOOGLE_include_directive : require
#include "params.glsl"

layout(location = 0) in vec3 position;
layout(location = 0) out float light_z;

void main() {
  float n = params.light.z;
  float f = params.sampling.w;
  float xy_scale = 2.0 * n / params.light.y;
  gl_Position = vec4(position.xy * xy_scale, (position.z - n) * f / (f - n), position.z);
  light_z = position.z;
#ifdef FLIP_Y
  gl_Position.y = -gl_Position.y;
#endif
}
