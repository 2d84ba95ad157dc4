// backprojection: the accurate algorithm of Dmitriev 2007 ("Soft Shadows",
// NVIDIA), after Guennebaud et al. 2006.
// Each occluding texel is the square patch of its frustum footprint at its
// depth; projected from the receiver P onto the light plane z = 0 it covers
// [(a0 - a_r) g(z), (a1 - a_r) g(z)] per axis, where a is the slope
// (u - 0.5) Fw / n and g(z) = z z_r / (z_r - z). Visibility is
// max(0, 1 - S / (2L)^2), S the sum of the projected areas inside the light.
// Texels at or behind the receiver are skipped. The min-max walk skips nodes
// that cannot touch the light and sums flat nodes whole;
// BACKPROJECTION_MAX_NODES bounds the nodes it visits (brute force: the
// texels it reads) and BACKPROJECTION_MAX_STEPS its steps, which a target
// may cap lower.
#include "common/minmax_traversal.glsl"

// Slopes (u - 0.5) Fw / n of map coordinates `uv`.
vec2 backprojection_slope(vec2 uv) {
  return (uv - 0.5) * (LIGHT_FRUSTUM_WIDTH / NEAR_PLANE);
}

// g(z): the factor from slope difference to light-plane distance.
float backprojection_gain(float z, float z_receiver) {
  return z * z_receiver / (z_receiver - z);
}

// Light-plane extent of texels `texels` (x0, y0, x1, y1) at linear depth z
// seen from the receiver with slopes `receiver_slope`: (X0, Y0, X1, Y1).
vec4 backprojection_project(vec4 texels, float z, vec3 query, vec2 receiver_slope) {
  float gain = backprojection_gain(z, query.z);
  return vec4((backprojection_slope(texels.xy * TEXEL_SIZE) - receiver_slope) * gain,
              (backprojection_slope((texels.zw + 1.0) * TEXEL_SIZE) - receiver_slope) * gain);
}

// The light's area (2L)^2.
float backprojection_whole_light_area() {
  return 4.0 * LIGHT_WORLD_SIZE * LIGHT_WORLD_SIZE;
}

// Area of a light-plane rectangle inside the light [-L, L]^2.
float backprojection_light_area(vec4 rect) {
  vec2 size = max(min(rect.zw, vec2(LIGHT_WORLD_SIZE)) - max(rect.xy, vec2(-LIGHT_WORLD_SIZE)),
                  vec2(0.0));
  return size.x * size.y;
}

// Whether texels at linear depth >= z_min can touch the light at all.
bool backprojection_can_touch(vec4 texels, float z_min, vec3 query, vec2 receiver_slope) {
  vec4 rect = backprojection_project(texels, z_min, query, receiver_slope);
  return all(lessThanEqual(rect.xy, vec2(LIGHT_WORLD_SIZE))) &&
         all(greaterThanEqual(rect.zw, vec2(-LIGHT_WORLD_SIZE)));
}

// The texels whose patches can reach the light from the receiver when no
// occluder is nearer than z_min, plus one texel, clipped to the map.
vec4 backprojection_window(vec3 query, float z_min) {
  float half_width = LIGHT_SIZE_UV * NEAR_PLANE * (query.z - z_min) / (query.z * z_min);
  vec2 map_size = params.shadow_map_size.xy;
  return minmax_clip_window(floor((query.xy - half_width) * map_size) - 1.0,
                            floor((query.xy + half_width) * map_size) + 1.0);
}

// S: the projected area inside the light of the texels with normalized
// depth below `limit` (they occlude and lie in front of the receiver),
// stopping at the light's area (2L)^2, after BACKPROJECTION_MAX_NODES
// nodes or texels, or after BACKPROJECTION_MAX_STEPS steps.
float backprojection_area(vec3 query, vec4 window, float limit) {
  vec2 receiver_slope = backprojection_slope(query.xy);
  float light_area = backprojection_whole_light_area();
  float area = 0.0;
  float visits = 0.0;
#if defined(PENUMBRA_TRAVERSAL_BRUTE_FORCE)
  vec2 texel = window.xy;
  bool done = false;
  MINMAX_FOR_BOUNDED(BACKPROJECTION_MAX_STEPS, done) {
    visits += 1.0;
    float depth = shadow_texel(texel);
    if (depth < limit) {
      vec4 rect = backprojection_project(texel.xyxy, depth * INV_DEPTH_SCALE, query,
                                         receiver_slope);
      area += backprojection_light_area(rect);
    }
    texel.x += 1.0;
    if (texel.x > window.z) texel = vec2(window.x, texel.y + 1.0);
    // MINMAX_FOR_BOUNDED rounds its bound up: stop at exactly the bound.
    done = texel.y > window.w || visits >= float(BACKPROJECTION_MAX_NODES);
  }
#else
  MinmaxCursor cursor = minmax_begin(window);
  MINMAX_FOR_BOUNDED(BACKPROJECTION_MAX_STEPS, cursor.done) {
    bool descend = false;
    if (!cursor.climbed) visits += 1.0;
    if (!cursor.climbed && !minmax_window_empty(minmax_node_part(cursor, window))) {
      vec2 range = minmax_cursor_read(cursor);
      vec4 texels = minmax_node_texels(cursor);
      float z_min = range.x * INV_DEPTH_SCALE;
      if (range.x < limit && backprojection_can_touch(texels, z_min, query, receiver_slope)) {
        if (range.y < limit && range.x == range.y) {
          area += backprojection_light_area(
              backprojection_project(texels, z_min, query, receiver_slope));
        } else {
          descend = cursor.level > 0.5;
        }
      }
    }
    if (descend) {
      minmax_descend(cursor);
    } else {
      minmax_next(cursor);
    }
    // Stop when the light is covered or the work bound is reached.
    cursor.done = cursor.done || area >= light_area ||
                  visits >= float(BACKPROJECTION_MAX_NODES);
  }
#endif
  return area;
}

float shadow_visibility(vec3 query) {
  // A point light (L = 0) has no area to cover: its shadow is hard's test
  // of the texel the receiver's ray to the light crosses.
  if (!(LIGHT_WORLD_SIZE > 0.0)) return shadow_compare_point(query.xy, query.z);
  // A texel occludes when d < reference; one at or behind the receiver
  // (a negative bias lets it pass) cannot be projected towards the light
  // (g(z) is infinite or negative) and is skipped, as the reference does.
  // DEPTH_SCALE is a power of two, so d < z_r DEPTH_SCALE is exactly z < z_r.
  float limit = min(shadow_reference(query.z), query.z * DEPTH_SCALE);
  // The top node (1x1) holds the map's minimum.
  float map_min = minmax_top_node().x;
  if (!(map_min < limit)) return 1.0;
  vec4 window = backprojection_window(query, map_min * INV_DEPTH_SCALE);
  if (minmax_window_empty(window)) return 1.0;
  return max(0.0, 1.0 - backprojection_area(query, window, limit) /
                            backprojection_whole_light_area());
}
