// minmax_pcf: the fast algorithm of Dmitriev 2007. 1 - C / K^2, C the occluding texels
// (d < reference) of the KERNEL_SIZE x KERNEL_SIZE window at
// floor(uv * size) - floor(K / 2); texels outside the map do not occlude.
// C is counted exactly: whole min-max nodes that all occlude or none do are
// answered without descending (PENUMBRA_TRAVERSAL_BRUTE_FORCE: every texel).
#include "common/minmax_traversal.glsl"

float minmax_pcf_count(vec2 first, float reference) {
  float count = 0.0;
#if defined(PENUMBRA_TRAVERSAL_BRUTE_FORCE)
  PENUMBRA_SAMPLE_LOOP for (int j = 0; j < KERNEL_SIZE; ++j) {
    PENUMBRA_SAMPLE_LOOP for (int i = 0; i < KERNEL_SIZE; ++i) {
      vec2 texel = first + vec2(float(i), float(j));
      bool inside = all(greaterThanEqual(texel, vec2(0.0))) &&
                    all(lessThan(texel, params.shadow_map_size.xy));
      if (inside && shadow_texel(texel) < reference) count += 1.0;
    }
  }
#else
  vec4 window = minmax_clip_window(first, first + float(KERNEL_SIZE - 1));
  if (minmax_window_empty(window)) return 0.0;
  MinmaxCursor cursor = minmax_begin(window);
  // MINMAX_MAX_VISITS bounds the nodes this walk can visit for any window.
  MINMAX_FOR_BOUNDED(MINMAX_MAX_VISITS, cursor.done) {
    vec4 part = minmax_node_part(cursor, window);
    bool descend = false;
    if (!minmax_window_empty(part)) {
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
  vec2 first = floor(query.xy * params.shadow_map_size.xy) - float(KERNEL_SIZE / 2);
  float count = minmax_pcf_count(first, shadow_reference(query.z));
  // C = 0 gives exactly 1 (K^2 times the rounded 1/K^2 can be 0.99999994).
  // Otherwise (K^2 - C) is exact and one correctly rounded product follows,
  // within one ulp of 1 - C / K^2 and exactly 0 for C = K^2: no compiler can
  // contract or reorder it, so every target rounds it alike. A division would
  // not be: GLSL allows it 2.5 ulp and HLSL compilers turn a division by a
  // constant into a reciprocal product.
  return count > 0.0 ? (float(KERNEL_SIZE * KERNEL_SIZE) - count) * MINMAX_PCF_INV_AREA : 1.0;
}
