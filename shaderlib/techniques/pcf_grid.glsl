// pcf_grid: mean of bilinear comparisons on a KERNEL_SIZE x KERNEL_SIZE grid
// of whole-texel offsets around the receiver.
float shadow_visibility(vec3 query) {
  const int radius = (KERNEL_SIZE - 1) / 2;
  float sum = 0.0;
  PENUMBRA_SAMPLE_LOOP for (int j = -radius; j <= radius; ++j) {
    PENUMBRA_SAMPLE_LOOP for (int i = -radius; i <= radius; ++i) {
      sum += shadow_compare_bilinear(query.xy + vec2(float(i), float(j)) * TEXEL_SIZE, query.z);
    }
  }
  return sum / float(KERNEL_SIZE * KERNEL_SIZE);
}
