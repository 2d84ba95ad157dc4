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
#if PENUMBRA_MAP_ATLAS
  // Last, so that the members before it keep their places: the light's
  // tile in the atlas (map_layout atlas), u and v of its first texel's outer
  // corner, its width and height, in texture coordinates.
  vec4 map_tile;
#elif PENUMBRA_MAP_ARRAY
  // Last, for the same reason: the light's layer of the array texture
  // (map_layout array) in x, a whole number; y, z, w: 0.
  vec4 map_layer;
#endif
} params;

#if PENUMBRA_MAP_ATLAS || PENUMBRA_MAP_ARRAY
// The light being shaded, which the caller of an atlas or array names per
// call (the query and deferred passes from the block, the function form
// from its arguments): its `light` and `sampling` members and its tile or
// layer.
vec4 call_light;
vec4 call_sampling;
#define PENUMBRA_LIGHT call_light
#define PENUMBRA_SAMPLING call_sampling
#endif

#if PENUMBRA_MAP_ATLAS
// The tile, and its size in texels (W, H, 1/W, 1/H), in which every
// technique works.
vec4 call_tile;
vec4 call_map_size;

void set_call(vec4 light, vec4 sampling, vec4 tile) {
  call_light = light;
  call_sampling = sampling;
  call_tile = tile;
  call_map_size = vec4(params.shadow_map_size.xy * tile.zw, params.shadow_map_size.zw / tile.zw);
}
#define PENUMBRA_CALL_FROM_PARAMS() set_call(params.light, params.sampling, params.map_tile)
#define PENUMBRA_MAP_SIZE call_map_size
#elif PENUMBRA_MAP_ARRAY
// The layer, as the array coordinate the texture functions take. Every
// layer has the array's size.
float call_layer;

void set_call(vec4 light, vec4 sampling, int layer) {
  call_light = light;
  call_sampling = sampling;
  call_layer = float(layer);
}
#define PENUMBRA_CALL_FROM_PARAMS() \
  set_call(params.light, params.sampling, int(params.map_layer.x))
#define PENUMBRA_MAP_SIZE params.shadow_map_size
#else
#define PENUMBRA_CALL_FROM_PARAMS()
#define PENUMBRA_LIGHT params.light
#define PENUMBRA_SAMPLING params.sampling
#define PENUMBRA_MAP_SIZE params.shadow_map_size
#endif

// The NVIDIA PCSS whitepaper's names for the same quantities.
#define LIGHT_WORLD_SIZE (PENUMBRA_LIGHT.x)
#define LIGHT_FRUSTUM_WIDTH (PENUMBRA_LIGHT.y)
#define NEAR_PLANE (PENUMBRA_LIGHT.z)
#define LIGHT_SIZE_UV (PENUMBRA_LIGHT.w)
#define FILTER_RADIUS_UV (PENUMBRA_SAMPLING.x)
#define DEPTH_BIAS (PENUMBRA_SAMPLING.y)
#define DEPTH_SCALE (PENUMBRA_SAMPLING.z)
#define INV_DEPTH_SCALE (PENUMBRA_SAMPLING.w)
// The map's size in texels and one texel in uv (an atlas's: its tile's).
#define MAP_SIZE (PENUMBRA_MAP_SIZE.xy)
#define TEXEL_SIZE (PENUMBRA_MAP_SIZE.zw)
#define MINMAX_TOP_LEVEL (params.minmax_info.x)

#endif
