// pcss: Percentage-Closer Soft Shadows, step for step as the NVIDIA
// whitepaper "Integrating Realistic Soft Shadows into Your Game Engine"
// (function names kept). The blocker search uses BLOCKER_DISK, the
// filtering PCF_DISK.

#include "techniques/pcss_filter.glsl"

void FindBlocker(out float avgBlockerDepth, out float numBlockers, vec2 uv, float zReceiver) {
  // Similar triangles give the region of the map to search; a directional
  // light's widens with the distance to the near plane alone.
#if PENUMBRA_ORTHOGRAPHIC
  float searchWidth = LIGHT_SIZE_UV * (zReceiver - NEAR_PLANE);
#else
  float searchWidth = LIGHT_SIZE_UV * (zReceiver - NEAR_PLANE) / zReceiver;
#endif
  float blockerSum = 0.0;
  numBlockers = 0.0;
  PENUMBRA_SAMPLE_LOOP for (int i = 0; i < BLOCKER_SEARCH_NUM_SAMPLES; ++i) {
    vec2 offset = BLOCKER_DISK_POINT(i) * searchWidth;
    float shadowMapDepth = shadow_depth_point(uv + offset);
    // Selects, not a branch: an `if` in this loop's body makes Direct3D
    // compilers' unrolling grow with each sample (vkd3d: minutes at 25).
    bool blocks = shadowMapDepth < PENUMBRA_PLANE_Z(zReceiver, offset) - DEPTH_BIAS;
    blockerSum += blocks ? shadowMapDepth : 0.0;
    numBlockers += blocks ? 1.0 : 0.0;
  }
  // The whitepaper divides unconditionally; PCSS() returns before using the
  // average when there is no blocker, so avoid the 0/0 here.
  avgBlockerDepth = numBlockers > 0.0 ? blockerSum / numBlockers : zReceiver;
}

float PCSS(vec3 coords) {
  vec2 uv = coords.xy;
  float zReceiver = coords.z;  // linear light-view z
  // Up to the near plane the search width is 0 or negative: a rendered map
  // holds nothing there to occlude the receiver.
  if (!(zReceiver > NEAR_PLANE)) return 1.0;

  // Step 1: blocker search.
  float avgBlockerDepth = 0.0;
  float numBlockers = 0.0;
  FindBlocker(avgBlockerDepth, numBlockers, uv, zReceiver);
  if (numBlockers < 1.0) {
    return 1.0;  // no occluder: fully lit, and filtering is skipped
  }

  // Step 2: penumbra size, the blocker no nearer than the near plane (as
  // pcss_minmax: a blocker at z = 0 would make the penumbra infinite).
#if PENUMBRA_ORTHOGRAPHIC
  // A directional light's penumbra: its slopes spread over the distance
  // from blocker to receiver.
  float filterRadiusUV = LIGHT_SIZE_UV * (zReceiver - max(avgBlockerDepth, NEAR_PLANE));
#else
  float penumbraRatio = PenumbraSize(zReceiver, max(avgBlockerDepth, NEAR_PLANE));
  float filterRadiusUV = penumbraRatio * LIGHT_SIZE_UV * NEAR_PLANE / coords.z;
#endif

  // Step 3: filtering.
  return PCF_Filter(uv, zReceiver, filterRadiusUV);
}

float shadow_visibility(vec3 query) {
  return PCSS(query);
}
