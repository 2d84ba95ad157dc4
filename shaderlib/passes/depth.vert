#version 450
// The NVIDIA PCSS whitepaper's step 1: render shadow casters from the light. Positions
// are in light-view space; the projection is docs/shader-interface.md's
// u = 0.5 + (x n / z) / Fw (x / Fw, orthographic), with clip z spanning
// [near_plane, 1/depth_scale].
#extension GL_GOOGLE_include_directive : require
#include "variant.glsl"
#include "common/params.glsl"

layout(location = 0) in vec3 position;
layout(location = 0) out float light_z;

void main() {
  float far_plane = INV_DEPTH_SCALE;
#if defined(PENUMBRA_MAP_ENCODING) && PENUMBRA_MAP_ENCODING == 3
  // A directional light's box: w = 1, depth affine in z.
  gl_Position = vec4(position.xy * (2.0 / LIGHT_FRUSTUM_WIDTH),
                     (position.z - NEAR_PLANE) / (far_plane - NEAR_PLANE), 1.0);
#else
  float xy_scale = 2.0 * NEAR_PLANE / LIGHT_FRUSTUM_WIDTH;
#if defined(PENUMBRA_MAP_ENCODING) && PENUMBRA_MAP_ENCODING == 2
  // Reversed-Z: depth 1 at the near plane, 0 at the far one.
  float clip_z = (far_plane - position.z) * NEAR_PLANE / (far_plane - NEAR_PLANE);
#else
  float clip_z = (position.z - NEAR_PLANE) * far_plane / (far_plane - NEAR_PLANE);
#endif
  gl_Position = vec4(position.xy * xy_scale, clip_z, position.z);
#endif
  light_z = position.z;
}
