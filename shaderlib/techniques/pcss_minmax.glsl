// pcss_minmax: PCSS whose blocker search reads the min-max mip instead of
// a disk: the <= 3x3 nodes at the finest level where the search window
// spans at most three nodes per axis. The blocker depth is the mean of the
// minima of the nodes that hold a blocker (minimum below the reference),
// each weighted by the window texels it covers, and at least the near
// plane; penumbra and filtering are pcss's (PCF over PCF_DISK).
// Reads: at most 9 + 4 PCF_NUM_SAMPLES, whatever the light size.
#include "common/minmax_traversal.glsl"
#include "techniques/pcss_filter.glsl"

// Whether the search window holds a blocker, and then the blockers' linear
// z: node minima weighted by the window texels of each node.
bool minmax_find_blocker(out float zBlocker, vec2 uv, float zReceiver, float reference) {
  zBlocker = zReceiver;
  // pcss's search region, a directional light's as well.
#if PENUMBRA_ORTHOGRAPHIC
  float searchWidth = LIGHT_SIZE_UV * (zReceiver - NEAR_PLANE);
#else
  float searchWidth = LIGHT_SIZE_UV * (zReceiver - NEAR_PLANE) / zReceiver;
#endif
  vec2 map_size = MAP_SIZE;
  vec4 window = minmax_clip_window(floor((uv - searchWidth) * map_size),
                                   floor((uv + searchWidth) * map_size));
  if (minmax_window_empty(window)) return false;
  float level = minmax_level_spanning(window, 3.0);
  float span = exp2(level);
  vec2 first = floor(window.xy / span);
  float depth_sum = 0.0;
  float texels = 0.0;
  PENUMBRA_SAMPLE_LOOP for (int j = 0; j < 3; ++j) {
    PENUMBRA_SAMPLE_LOOP for (int i = 0; i < 3; ++i) {
      vec2 node = first + vec2(float(i), float(j));
      vec4 part = vec4(max(node * span, window.xy), min(node * span + span - 1.0, window.zw));
      // No `continue`: Shader Model 3 compilers (vkd3d) have none.
      if (!minmax_window_empty(part)) {
        float node_min = minmax_node(level, node).x;
        if (node_min < reference) {
          float weight = minmax_texel_count(part);
          depth_sum += node_min * weight;
          texels += weight;
        }
      }
    }
  }
  if (texels < 0.5) return false;
  zBlocker = depth_sum / texels * INV_DEPTH_SCALE;
  return true;
}

float shadow_visibility(vec3 query) {
  if (!(query.z > NEAR_PLANE)) return 1.0;  // up to the near plane, lit, as pcss
  float zBlocker = 0.0;
  if (!minmax_find_blocker(zBlocker, query.xy, query.z, shadow_normalized_reference(query.z))) {
    return 1.0;  // no blocker: fully lit
  }
  // A rendered map holds nothing nearer than the near plane; a blocker there
  // (z = 0 in a hand-made map) would make the penumbra infinite.
  zBlocker = max(zBlocker, NEAR_PLANE);
#if PENUMBRA_ORTHOGRAPHIC
  float filterRadiusUV = LIGHT_SIZE_UV * (query.z - zBlocker);  // pcss's directional width
#else
  float filterRadiusUV = PenumbraSize(query.z, zBlocker) * LIGHT_SIZE_UV * NEAR_PLANE / query.z;
#endif
  return PCF_Filter(query.xy, query.z, filterRadiusUV);
}
