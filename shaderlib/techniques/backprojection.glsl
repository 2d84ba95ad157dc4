// backprojection: the accurate algorithm of Dmitriev 2007 ("Soft Shadows",
// NVIDIA), after Guennebaud et al. 2006. Visibility is
// max(0, 1 - S / (2L)^2), S the sum of the occluding patches' projected
// areas inside the light (common/backprojection_walk.glsl): overlapping
// patches are counted twice.

// The walk's state: S so far.
#define BackprojectionState float

// The light's area (2L)^2.
float backprojection_whole_light_area() {
  return 4.0 * LIGHT_WORLD_SIZE * LIGHT_WORLD_SIZE;
}

// The area of a light-plane rectangle inside the light [-L, L]^2.
float backprojection_inside(vec4 rect) {
  vec2 size = max(min(rect.zw, vec2(LIGHT_WORLD_SIZE)) - max(rect.xy, vec2(-LIGHT_WORLD_SIZE)),
                  vec2(0.0));
  return size.x * size.y;
}

// `area` plus the rectangle's area inside the light.
float backprojection_add(float area, vec4 rect) {
  return area + backprojection_inside(rect);
}

// `area` plus `share` of the rectangle's area inside the light: a node the
// capped walk takes whole (common/backprojection_walk.glsl).
float backprojection_add_share(float area, vec4 rect, float share) {
  return area + share * backprojection_inside(rect);
}

bool backprojection_covered(float area) {
  return area >= backprojection_whole_light_area();
}

#include "common/backprojection_walk.glsl"

float shadow_visibility(vec3 query) {
  if (!(LIGHT_WORLD_SIZE > 0.0)) return shadow_compare_point(query.xy, query.z);
  float limit;
  vec4 window;
  if (!backprojection_start(query, limit, window)) return 1.0;
  float area = backprojection_walk(query, window, limit, 0.0);
  return max(0.0, 1.0 - area / backprojection_whole_light_area());
}
