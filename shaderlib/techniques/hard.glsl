// hard: the lit test of the nearest texel.
float shadow_visibility(vec3 query) {
  return shadow_compare_point(query.xy, query.z);
}
