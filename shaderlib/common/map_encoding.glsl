// The map's encoding (the map_encoding key, docs/techniques.md, "Map
// encodings"): PENUMBRA_MAP_ENCODING 0 or unset, linear z * DEPTH_SCALE; 1,
// the hardware depth of a perspective projection from NEAR_PLANE to
// 1 / DEPTH_SCALE; 2, the same reversed-Z; 3, the depth of an orthographic
// projection over the same planes (a directional light).
#ifndef PENUMBRA_MAP_ENCODING_GLSL
#define PENUMBRA_MAP_ENCODING_GLSL

#include "common/params.glsl"

#ifndef PENUMBRA_MAP_ENCODING
#define PENUMBRA_MAP_ENCODING 0
#endif

// An orthographic map's light is directional (docs/techniques.md, "Map
// encodings"): PCSS's search and penumbra widths follow.
#define PENUMBRA_ORTHOGRAPHIC (PENUMBRA_MAP_ENCODING == 3)

#if PENUMBRA_MAP_ENCODING == 0
// Linear z: macros, so that the library's own maps compile to the text they
// always did.
#define shadow_encode(z) ((z) * DEPTH_SCALE)
#define shadow_linear(stored) ((stored) * INV_DEPTH_SCALE)
#elif PENUMBRA_MAP_ENCODING == 3
// Orthographic depth is affine in z: the planes' weights, exact at both ends.
float shadow_encode(float z) {
  return (z - NEAR_PLANE) / (INV_DEPTH_SCALE - NEAR_PLANE);
}
float shadow_linear(float stored) {
  return (1.0 - stored) * NEAR_PLANE + stored * INV_DEPTH_SCALE;
}
#else
// The stored value for linear z. Written as a quotient of differences, not
// A - B / z: its float32 error stays within a few ulp of the stored value,
// which the reference's tie margin allows for.
float shadow_encode(float z) {
#if PENUMBRA_MAP_ENCODING == 1
  return (z - NEAR_PLANE) * INV_DEPTH_SCALE / (z * (INV_DEPTH_SCALE - NEAR_PLANE));
#else
  return (INV_DEPTH_SCALE - z) * NEAR_PLANE / (z * (INV_DEPTH_SCALE - NEAR_PLANE));
#endif
}

// Linear z of a stored value: n f over a weighted sum of the planes, which
// stays exact at both ends (the far plane gives f, not n f / 0) however far
// the far plane lies.
float shadow_linear(float stored) {
#if PENUMBRA_MAP_ENCODING == 1
  return NEAR_PLANE * INV_DEPTH_SCALE /
         ((1.0 - stored) * INV_DEPTH_SCALE + stored * NEAR_PLANE);
#else
  return NEAR_PLANE * INV_DEPTH_SCALE /
         (stored * INV_DEPTH_SCALE + (1.0 - stored) * NEAR_PLANE);
#endif
}
#endif

// Normalized linear depth z(d) * DEPTH_SCALE, z(d) / f, of a stored value:
// what the min-max techniques work in. Their mip is built from it
// (passes/minmax_init.frag), and back-projection and the blocker average
// need z. shadow_linear()'s weights over f, with f cancelled: a product
// fewer per read, which hlsl_dx9's slots count.
#if PENUMBRA_MAP_ENCODING == 0
#define shadow_normalized(stored) (stored)
#elif PENUMBRA_MAP_ENCODING == 3
float shadow_normalized(float stored) {
  return (1.0 - stored) * (NEAR_PLANE * DEPTH_SCALE) + stored;
}
#else
float shadow_normalized(float stored) {
#if PENUMBRA_MAP_ENCODING == 1
  return NEAR_PLANE / ((1.0 - stored) * INV_DEPTH_SCALE + stored * NEAR_PLANE);
#else
  return NEAR_PLANE / (stored * INV_DEPTH_SCALE + (1.0 - stored) * NEAR_PLANE);
#endif
}
#endif

// Whether a stored texel lets a receiver with stored reference `reference`
// see the light: reversed-Z stores the nearer surface as the larger value.
#if PENUMBRA_MAP_ENCODING == 2
#define PENUMBRA_LIT(reference, texel) ((reference) >= (texel))
#else
#define PENUMBRA_LIT(reference, texel) ((reference) <= (texel))
#endif

#endif
