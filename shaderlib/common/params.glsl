// ShadowParams: every parameter a pass reads (docs/shader-interface.md).
// All members are vec4 so that Direct3D 9 constant registers map one to one.
#ifndef PENUMBRA_PARAMS_GLSL
#define PENUMBRA_PARAMS_GLSL

layout(set = 0, binding = PENUMBRA_SLOT_PARAMS, std140) uniform ShadowParams {
  vec4 shadow_map_size;  // W, H, 1/W, 1/H
  vec4 light;            // light_world_size, light_frustum_width, near_plane, light size in uv
  vec4 sampling;         // filter_radius_uv, bias, depth_scale, 1/depth_scale
  vec4 screen_size;      // output width, height, 1/width, 1/height
  vec4 source_size;      // min-max build passes: the level they read: W, H, 1/W, 1/H
  vec4 minmax_info;      // x: the min-max mip's top level N (1x1); y, z, w: 0
#if PENUMBRA_DEFERRED_PARAMS
  // The deferred pass only, after the members every pass shares: matrices
  // column by column, as a column-major mat4 is stored.
  vec4 camera_inverse_0;    // the inverse of the camera's view-projection
  vec4 camera_inverse_1;
  vec4 camera_inverse_2;
  vec4 camera_inverse_3;
  vec4 light_view_proj_0;   // the light's view-projection, which drew the map
  vec4 light_view_proj_1;
  vec4 light_view_proj_2;
  vec4 light_view_proj_3;
  vec4 camera_depth_range;  // clip z / w = x depth + y; z: the cleared depth; w: 0
#endif
} params;

// The NVIDIA PCSS whitepaper's names for the same quantities.
#define LIGHT_WORLD_SIZE (params.light.x)
#define LIGHT_FRUSTUM_WIDTH (params.light.y)
#define NEAR_PLANE (params.light.z)
#define LIGHT_SIZE_UV (params.light.w)
#define FILTER_RADIUS_UV (params.sampling.x)
#define DEPTH_BIAS (params.sampling.y)
#define DEPTH_SCALE (params.sampling.z)
#define INV_DEPTH_SCALE (params.sampling.w)
#define TEXEL_SIZE (params.shadow_map_size.zw)
#define MINMAX_TOP_LEVEL (params.minmax_info.x)

#endif
