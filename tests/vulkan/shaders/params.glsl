// ShadowParams as docs/shader-interface.md lays it out. The member the doc
// calls `filter` is `sampling` here, as in shaderlib/common/params.glsl:
// `filter` is a reserved word in GLSL.
layout(set = 0, binding = 0, std140) uniform ShadowParams {
  vec4 shadow_map_size;  // W, H, 1/W, 1/H
  vec4 light;            // L, Fw, n, L/Fw
  vec4 sampling;         // filter radius, bias, depth_scale, 1/depth_scale
  vec4 screen_size;      // width, height, 1/width, 1/height
  vec4 source_size;      // min-max build passes: the level they read: W, H, 1/W, 1/H
  vec4 minmax_info;      // x: the min-max mip's top level N
} params;
