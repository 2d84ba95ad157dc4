#version 450
// Query pass: reads the receiver (u, v, z_r) at this pixel and writes the
// variant's visibility in [0, 1] to .x and, for debugging, the shadow-map
// and min-max texels it read to .y.
#extension GL_GOOGLE_include_directive : require
#include "variant.glsl"
#include "techniques/technique.glsl"

layout(set = 0, binding = PENUMBRA_SLOT_RECEIVERS) uniform sampler2D receivers;

layout(location = 0) in vec2 screen_uv;  // this pixel's centre in [0, 1]
layout(location = 0) out vec4 visibility;

void main() {
  penumbra_texel_reads = 0.0;
  PENUMBRA_CALL_FROM_PARAMS();
  vec3 query = textureLod(receivers, screen_uv, 0.0).xyz;
#if PENUMBRA_RECEIVER_PLANE
  penumbra_depth_slope = receiver_depth_slope(dFdx(query), dFdy(query), query.z);
#endif
  // The receiver's pixel, counted as the receivers image counts it on every
  // API (gl_FragCoord's rows run the other way on OpenGL, and Direct3D 9's
  // VPOS is not what a translator of its bytecode reads).
  float visible = receiver_visibility(query, floor(screen_uv * params.screen_size.xy));
  visibility = vec4(visible, penumbra_texel_reads, 0.0, 0.0);
}
