// pcf_poisson: mean of bilinear comparisons over a Poisson disk of radius
// FILTER_RADIUS_UV (a uniform-size penumbra).
float shadow_visibility(vec3 query) {
  float sum = 0.0;
  for (int i = 0; i < PCF_NUM_SAMPLES; ++i) {
    sum += shadow_compare_bilinear(query.xy + PCF_DISK[i] * FILTER_RADIUS_UV, query.z);
  }
  return sum / float(PCF_NUM_SAMPLES);
}
