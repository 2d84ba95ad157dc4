// Shadow-map reads and comparisons. This is the one place where targets
// differ: PENUMBRA_HAS_COMPARISON_SAMPLER (set by the compiler per target)
// chooses the hardware comparison sampler or in-shader compares (Direct3D 9).
// The map holds normalized depth d = z * DEPTH_SCALE (a power of two, exact),
// or with PENUMBRA_MAP_ENCODING (the map_encoding key) an engine's hardware
// depth for a projection from NEAR_PLANE to 1 / DEPTH_SCALE: 1, perspective;
// 2, perspective reversed-Z; 3, orthographic (docs/techniques.md, "Map
// encodings"). With PENUMBRA_MAP_ATLAS the map is a tile of its texture,
// with PENUMBRA_MAP_ARRAY a layer of a 2D array texture (map_layout).
#ifndef PENUMBRA_SHADOW_MAP_GLSL
#define PENUMBRA_SHADOW_MAP_GLSL

#include "common/map_encoding.glsl"
#include "common/params.glsl"

#if PENUMBRA_MAP_ARRAY
layout(set = 0, binding = PENUMBRA_SLOT_SHADOW_DEPTH) uniform sampler2DArray shadow_depth;
layout(set = 0, binding = PENUMBRA_SLOT_SHADOW_CMP) uniform sampler2DArrayShadow shadow_cmp;
#else
layout(set = 0, binding = PENUMBRA_SLOT_SHADOW_DEPTH) uniform sampler2D shadow_depth;
#if PENUMBRA_HAS_COMPARISON_SAMPLER
layout(set = 0, binding = PENUMBRA_SLOT_SHADOW_CMP) uniform sampler2DShadow shadow_cmp;
#endif
#endif
// Shadow-map and mip texels read so far (the query pass's debug output .y):
// a point read or a min-max node counts 1, a bilinear comparison 4. The
// query pass zeroes it first.
float penumbra_texel_reads;

#if PENUMBRA_RECEIVER_PLANE
// The `receiver_plane` key (receiver-plane depth bias, Schuler 2006): the
// receiver's depth slope (dz/du, dz/dv), set by the query pass, moves each
// sample's reference along the receiver's plane, so a sloped receiver does
// not shadow itself across a wide filter.
vec2 penumbra_depth_slope;

// A receiver steeper than this, in z per unit of distance across the
// light's view (about 84 degrees from facing the light), has no plane: a
// quad across a depth discontinuity gives such slopes.
#define PENUMBRA_MAX_PLANE_TANGENT 10.0

// (dz/du, dz/dv) at linear depth z from the screen derivatives of (u, v, z):
// the inverse Jacobian of (u, v) times (dz/dx, dz/dy); (0, 0) where that is
// singular or too steep.
vec2 receiver_depth_slope(vec3 dx, vec3 dy, float z) {
  float det = dx.x * dy.y - dy.x * dx.y;
  vec2 scaled = vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z);
  // One unit of u or v spans Fw z / n across the light's view at depth z
  // (Fw at every depth, orthographic).
#if PENUMBRA_ORTHOGRAPHIC
  float limit = PENUMBRA_MAX_PLANE_TANGENT * LIGHT_FRUSTUM_WIDTH;
#else
  float limit = PENUMBRA_MAX_PLANE_TANGENT * (LIGHT_FRUSTUM_WIDTH / NEAR_PLANE) * z;
#endif
  // Tested before dividing (`<` is false for NaN and infinities), and 0 / 0
  // (a quad whose row and column see the same two receivers) never computed:
  // hlsl_dx9's bytecode let that NaN through the select.
  bool planar = all(lessThan(abs(scaled), vec2(limit * abs(det))));
  float divisor = planar ? det : 1.0;
  return planar ? scaled / divisor : vec2(0.0);
}

// z_r moved along the receiver's plane to a sample at uv offset `offset`.
#define PENUMBRA_PLANE_Z(z, offset) ((z) + dot(penumbra_depth_slope, offset))
#else
#define PENUMBRA_PLANE_Z(z, offset) (z)
#endif

#if PENUMBRA_MAP_ATLAS
// Where uv of the light's own map lies in the atlas: clamped to the tile's
// outermost texel centres first, so that a read at or beyond the map's edge
// returns its edge texel, as clamp addressing does for a map of its own, and
// no read leaves the tile (docs/techniques.md, "Map layouts").
vec2 map_uv(vec2 uv) {
  vec2 half_texel = 0.5 * TEXEL_SIZE;
  return call_tile.xy + clamp(uv, half_texel, 1.0 - half_texel) * call_tile.zw;
}
#else
#define map_uv(uv) (uv)
#endif

// The stored value of the texel nearest to uv; the comparison with the
// hardware's bilinear filter, level 0. A layer clamps its reads as a map of
// its own does. GLSL has no textureLod on a sampler2DArrayShadow: zero
// gradients choose level 0 (every target's SampleCmpLevelZero).
#if PENUMBRA_MAP_ARRAY
#define MAP_READ(uv) textureLod(shadow_depth, vec3(uv, call_layer), 0.0).r
#define MAP_COMPARE(uv, reference) \
  textureGrad(shadow_cmp, vec4(uv, call_layer, reference), vec2(0.0), vec2(0.0))
#else
#define MAP_READ(uv) textureLod(shadow_depth, map_uv(uv), 0.0).r
#define MAP_COMPARE(uv, reference) textureLod(shadow_cmp, vec3(map_uv(uv), reference), 0.0)
#endif

// Linear light-view z of the texel nearest to uv (point sampling).
float shadow_depth_point(vec2 uv) {
  penumbra_texel_reads += 1.0;
  return shadow_linear(MAP_READ(uv));
}

// The comparison reference for a receiver: biased and stored like the map.
float shadow_reference(float z_receiver) {
  return shadow_encode(z_receiver - DEPTH_BIAS);
}

// 1 when the nearest texel lets the receiver see the light (z_r <= depth).
float shadow_compare_point(vec2 uv, float z_receiver) {
  penumbra_texel_reads += 1.0;
  return PENUMBRA_LIT(shadow_reference(z_receiver), MAP_READ(uv)) ? 1.0 : 0.0;
}

// Bilinear comparison: the four texels around uv, each compared, blended
// with bilinear weights (SampleCmpLevelZero with a linear comparison filter).
float shadow_compare_bilinear(vec2 uv, float z_receiver) {
  penumbra_texel_reads += 4.0;
  float reference = shadow_reference(z_receiver);
#if PENUMBRA_HAS_COMPARISON_SAMPLER
  return MAP_COMPARE(uv, reference);
#else
  vec2 texel = uv * MAP_SIZE - 0.5;
  vec2 corner = floor(texel);
  vec2 weight = texel - corner;
  // Centres of the four texels; clamp addressing (an atlas: map_uv) handles
  // the map's edges.
  vec2 uv00 = (corner + 0.5) * TEXEL_SIZE;
  vec2 uv11 = uv00 + TEXEL_SIZE;
  float lit00 = PENUMBRA_LIT(reference, MAP_READ(uv00)) ? 1.0 : 0.0;
  float lit10 = PENUMBRA_LIT(reference, MAP_READ(vec2(uv11.x, uv00.y))) ? 1.0 : 0.0;
  float lit01 = PENUMBRA_LIT(reference, MAP_READ(vec2(uv00.x, uv11.y))) ? 1.0 : 0.0;
  float lit11 = PENUMBRA_LIT(reference, MAP_READ(uv11)) ? 1.0 : 0.0;
  return mix(mix(lit00, lit10, weight.x), mix(lit01, lit11, weight.x), weight.y);
#endif
}

// The reference the min-max techniques compare their normalized linear
// depths (shadow_normalized()) with: (z_r - bias) * DEPTH_SCALE.
#if PENUMBRA_MAP_ENCODING == 0
#define shadow_normalized_reference(z_receiver) shadow_reference(z_receiver)
#else
#define shadow_normalized_reference(z_receiver) (((z_receiver) - DEPTH_BIAS) * DEPTH_SCALE)
#endif

// Normalized linear depth of map texel `texel` (integer coordinates), point
// read.
float shadow_texel(vec2 texel) {
  penumbra_texel_reads += 1.0;
  return shadow_normalized(MAP_READ((texel + 0.5) * TEXEL_SIZE));
}

#endif
