// pcf_poisson: mean of bilinear comparisons over a Poisson disk of radius
// FILTER_RADIUS_UV (a uniform-size penumbra).
#include "common/disks.glsl"

float shadow_visibility(vec3 query) {
  float sum = 0.0;
  PENUMBRA_SAMPLE_LOOP for (int i = 0; i < PCF_NUM_SAMPLES; ++i) {
    vec2 offset = PCF_DISK_POINT(i) * FILTER_RADIUS_UV;
    sum += shadow_compare_bilinear(query.xy + offset, PENUMBRA_PLANE_Z(query.z, offset));
  }
  return sum / float(PCF_NUM_SAMPLES);
}
