#version 450
// The NVIDIA PCSS whitepaper's step 1: write linear light-view z (normalized by the
// power-of-two DEPTH_SCALE, so exact) to the R32F target and to the depth
// buffer, so one pass fills an R32F map (Direct3D 9) or a depth map. For a
// map_encoding the depth buffer keeps the rasterizer's depth, as an engine's
// depth-only pass leaves it, and the R32F target gets the same encoding.
#extension GL_GOOGLE_include_directive : require
#include "variant.glsl"
#include "common/map_encoding.glsl"

layout(location = 0) in float light_z;
layout(location = 0) out float depth_out;

void main() {
  float stored = shadow_encode(light_z);
  depth_out = stored;
#if PENUMBRA_MAP_ENCODING == 0
  gl_FragDepth = stored;
#endif
}
