// Selects the technique named by the variant's PENUMBRA_TECHNIQUE_* define.
#include "common/shadow_map.glsl"

#if defined(PENUMBRA_TECHNIQUE_HARD)
#include "techniques/hard.glsl"
#elif defined(PENUMBRA_TECHNIQUE_PCF_GRID)
#include "techniques/pcf_grid.glsl"
#elif defined(PENUMBRA_TECHNIQUE_PCF_POISSON)
#include "techniques/pcf_poisson.glsl"
#elif defined(PENUMBRA_TECHNIQUE_PCSS)
#include "techniques/pcss.glsl"
#elif defined(PENUMBRA_TECHNIQUE_MINMAX_PCF)
#include "techniques/minmax_pcf.glsl"
#elif defined(PENUMBRA_TECHNIQUE_BACKPROJECTION)
#include "techniques/backprojection.glsl"
#elif defined(PENUMBRA_TECHNIQUE_PCSS_MINMAX)
#include "techniques/pcss_minmax.glsl"
#elif defined(PENUMBRA_TECHNIQUE_SCREEN_BLUR)
#include "techniques/screen_blur.glsl"
#elif defined(PENUMBRA_TECHNIQUE_BITMASK_BACKPROJECTION)
#include "techniques/bitmask_backprojection.glsl"
#else
#error "no PENUMBRA_TECHNIQUE_* defined"
#endif

// Receivers beyond this depth (2^60) are taken at it: behind any occluder,
// and a product of two depths stays a finite float.
#define PENUMBRA_MAX_RECEIVER_DEPTH 1152921504606846976.0

// The technique's visibility for any receiver (docs/robustness.md): one at
// or behind the light is lit, as is a NaN depth (`!(>)` holds for it).
// `pixel` (integer column and row of the receiver) places the samples of a
// variant with the `rotation` key.
float receiver_visibility(vec3 query, vec2 pixel) {
#if PENUMBRA_ROTATION_IGN
  penumbra_begin_pixel(pixel);
#endif
  if (!(query.z > 0.0)) return 1.0;
  return shadow_visibility(vec3(query.xy, min(query.z, PENUMBRA_MAX_RECEIVER_DEPTH)));
}
