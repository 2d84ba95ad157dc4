// screen_blur (GameDev.net, "Soft-Edged Shadows"): the unblurred screen
// factor, the mean of 3x3 point compares at whole-texel offsets (i / W,
// j / H), i, j in -1..1, around the receiver. blur_h, blur_v and composite
// (common/blur.glsl) filter it later.
float shadow_visibility(vec3 query) {
  float sum = 0.0;
  for (int j = -1; j <= 1; ++j) {
    for (int i = -1; i <= 1; ++i) {
      sum += shadow_compare_point(query.xy + vec2(float(i), float(j)) * TEXEL_SIZE, query.z);
    }
  }
  return sum / 9.0;
}
