// minmax_pcf: the fast algorithm of Dmitriev 2007. 1 - C / K^2, C the occluding texels
// (d < reference) of the KERNEL_SIZE x KERNEL_SIZE window at
// floor(uv * size) - floor(K / 2); texels outside the map do not occlude.
// C is counted exactly: whole min-max nodes that all occlude or none do are
// answered without descending (PENUMBRA_TRAVERSAL_BRUTE_FORCE: every texel,
// row by row). MINMAX_MAX_STEPS bounds the steps of either; where a target
// caps it below what the window needs, C counts what the steps reached.
#include "common/minmax_traversal.glsl"

// The walk's loop over its steps: one loop where they fit one.
#if MINMAX_MAX_STEPS <= 255
#define MINMAX_PCF_FOR_STEPS(done) MINMAX_FOR_ONE_LOOP(MINMAX_MAX_STEPS, done)
#else
#define MINMAX_PCF_FOR_STEPS(done) MINMAX_FOR_BOUNDED(MINMAX_MAX_STEPS, done)
#endif

float minmax_pcf_count(vec2 first, float reference) {
  float count = 0.0;
  vec4 window = minmax_clip_window(first, first + float(KERNEL_SIZE - 1));
  if (minmax_window_empty(window)) return 0.0;
#if defined(PENUMBRA_TRAVERSAL_BRUTE_FORCE)
  vec2 texel = window.xy;
  float steps = 0.0;
  bool done = false;
  MINMAX_PCF_FOR_STEPS(done) {
    if (shadow_texel(texel) < reference) count += 1.0;
    texel.x += 1.0;
    if (texel.x > window.z) texel = vec2(window.x, texel.y + 1.0);
    // Three loops round the bound up: stop at exactly the bound.
    steps += 1.0;
    done = texel.y > window.w || steps >= float(MINMAX_MAX_STEPS);
  }
#else
  MinmaxCursor cursor = minmax_begin(window);
  MINMAX_PCF_FOR_STEPS(cursor.done) {
    vec4 part = minmax_node_part(cursor, window);
    bool descend = false;
    if (!cursor.climbed && !minmax_window_empty(part)) {
      vec2 range = minmax_cursor_read(cursor);
      if (range.y < reference) {
        count += minmax_texel_count(part);  // every texel occludes
      } else {
        descend = reference > range.x && cursor.level > 0.5;  // some do
      }
    }
    if (descend) {
      minmax_descend(cursor);
    } else {
      minmax_next(cursor);
    }
  }
#endif
  return count;
}

float shadow_visibility(vec3 query) {
  vec2 first = floor(query.xy * MAP_SIZE) - float(KERNEL_SIZE / 2);
  float count = minmax_pcf_count(first, shadow_normalized_reference(query.z));
  // C = 0 gives exactly 1 (K^2 times the rounded 1/K^2 can be 0.99999994).
  // Otherwise (K^2 - C) is exact and one correctly rounded product follows,
  // within one ulp of 1 - C / K^2 and exactly 0 for C = K^2: no compiler can
  // contract or reorder it, so every target rounds it alike. A division would
  // not be: GLSL allows it 2.5 ulp and HLSL compilers turn a division by a
  // constant into a reciprocal product.
  return count > 0.0 ? (float(KERNEL_SIZE * KERNEL_SIZE) - count) * MINMAX_PCF_INV_AREA : 1.0;
}
