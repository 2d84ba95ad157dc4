// The back-projection of Guennebaud et al. 2006 as Dmitriev 2007 ("Soft
// Shadows", NVIDIA) walks it, shared by backprojection (sums areas) and
// bitmask_backprojection (sets light-sample bits).
// Each occluding texel is the square patch of its frustum footprint at its
// depth; projected from the receiver P onto the light plane z = 0 it covers
// [(a0 - a_r) g(z), (a1 - a_r) g(z)] per axis, where a is the slope
// (u - 0.5) Fw / n and g(z) = z z_r / (z_r - z). Texels at or behind the
// receiver are skipped. The min-max walk skips nodes that cannot touch the
// light and hands flat nodes over whole; BACKPROJECTION_MAX_NODES bounds
// the nodes it visits (brute force: the texels it reads) and
// BACKPROJECTION_MAX_STEPS its steps, which a target may cap lower.
// The including technique defines, before including this file, its
// BackprojectionState, backprojection_add(state, rect), which returns the
// state after one projected rectangle, and backprojection_covered(state),
// true once the light is covered; with BACKPROJECTION_FINISH_COARSE also
// backprojection_add_share(state, rect, share), which adds that share of it.
//
// BACKPROJECTION_FINISH_COARSE (a target's cap on the steps binds: hlsl_dx9)
// makes the min-max walk finish rather than stop: a node it cannot refine
// and still end within the steps is taken whole, one patch at its min
// depth, all of it where every texel occludes and half where some may not.
// Guennebaud et al. back-project a coarser level of the map for wide
// penumbrae alike; the error is bounded by the nodes so taken
// (docs/targets.md).
#ifndef PENUMBRA_BACKPROJECTION_WALK_GLSL
#define PENUMBRA_BACKPROJECTION_WALK_GLSL

#include "common/minmax_traversal.glsl"

// The walk's loop over its steps: one loop where they fit one.
#if BACKPROJECTION_MAX_STEPS <= 255
#define BACKPROJECTION_FOR_STEPS(done) MINMAX_FOR_ONE_LOOP(BACKPROJECTION_MAX_STEPS, done)
#else
#define BACKPROJECTION_FOR_STEPS(done) MINMAX_FOR_BOUNDED(BACKPROJECTION_MAX_STEPS, done)
#endif

// The factor from map coordinates to slopes (u - 0.5) Fw / n, Fw / n; under
// a directional light (an orthographic map), to positions across its box, Fw.
float backprojection_to_slope() {
#if PENUMBRA_ORTHOGRAPHIC
  return LIGHT_FRUSTUM_WIDTH;
#else
  return LIGHT_FRUSTUM_WIDTH / NEAR_PLANE;
#endif
}

// g(z): the factor from slope difference to light-plane distance; under a
// directional light, from position difference to the slope of the
// direction, whose square [-L, L]^2 is then the light.
float backprojection_gain(float z, float z_receiver) {
#if PENUMBRA_ORTHOGRAPHIC
  return 1.0 / (z_receiver - z);
#else
  return z * z_receiver / (z_receiver - z);
#endif
}

// Light-plane extent of texels `texels` (x0, y0, x1, y1) at linear depth z
// seen from the receiver `query`: (X0, Y0, X1, Y1). The map coordinates
// are subtracted before they are scaled: near the receiver, slopes
// subtracted would cancel their rounding into an error g(z) times theirs,
// which a receiver just below an occluder's edge (g large) would see.
// Both corners in one vec4, lane for lane the same arithmetic: Shader Model
// 3 counts a vec4 operation as one slot.
vec4 backprojection_project(vec4 texels, float z, vec3 query) {
  float scale = backprojection_gain(z, query.z) * backprojection_to_slope();
  vec4 corners = vec4(texels.xy, texels.zw + 1.0) * TEXEL_SIZE.xyxy;
  return (corners - query.xyxy) * scale;
}

// Whether a light-plane rectangle meets the light. For texels projected at
// their min depth: whether they can touch it at all (g grows with z).
// One all() of four lanes: && would be a branch (Shader Model 3 slots).
bool backprojection_touches(vec4 rect) {
  return all(lessThanEqual(rect * vec4(1.0, 1.0, -1.0, -1.0), vec4(LIGHT_WORLD_SIZE)));
}

// The texels whose patches can reach the light from the receiver when no
// occluder is nearer than z_min, plus one texel, clipped to the map.
vec4 backprojection_window(vec3 query, float z_min) {
#if PENUMBRA_ORTHOGRAPHIC
  float half_width = LIGHT_SIZE_UV * (query.z - z_min);
#else
  float half_width = LIGHT_SIZE_UV * NEAR_PLANE * (query.z - z_min) / (query.z * z_min);
#endif
  vec2 map_size = MAP_SIZE;
  return minmax_clip_window(floor((query.xy - half_width) * map_size) - 1.0,
                            floor((query.xy + half_width) * map_size) + 1.0);
}

// Returns `state` after handing backprojection_add() the projection of
// every texel of `window` with normalized depth below `limit` (it occludes
// and lies in front of the receiver), flat nodes whole, until
// backprojection_covered(), after BACKPROJECTION_MAX_NODES nodes or texels,
// or after BACKPROJECTION_MAX_STEPS steps.
BackprojectionState backprojection_walk(vec3 query, vec4 window, float limit,
                                        BackprojectionState state) {
  float visits = 0.0;
#if defined(PENUMBRA_TRAVERSAL_BRUTE_FORCE)
  vec2 texel = window.xy;
  bool done = false;
  BACKPROJECTION_FOR_STEPS(done) {
    visits += 1.0;
    float depth = shadow_texel(texel);
    if (depth < limit) {
      state = backprojection_add(
          state,
          backprojection_project(texel.xyxy, depth * INV_DEPTH_SCALE, query));
    }
    texel.x += 1.0;
    if (texel.x > window.z) texel = vec2(window.x, texel.y + 1.0);
    // Three loops round the bound up: stop at exactly the bound.
    done = texel.y > window.w || visits >= float(BACKPROJECTION_MAX_NODES);
  }
#else
  MinmaxCursor cursor = minmax_begin(window);
#if defined(BACKPROJECTION_FINISH_COARSE)
  // The steps to the walk's end if it descends no further, this one
  // included: 4 at the roots; a step takes one, a descent adds four (the
  // children, then the rise past them). Descending only where the walk then
  // still ends within its steps, it always ends, and descends wherever the
  // uncapped walk would if that one fits.
  float steps_to_end = 4.0;
  float steps_left = float(BACKPROJECTION_MAX_STEPS);
#endif
  BACKPROJECTION_FOR_STEPS(cursor.done) {
    bool descend = false;
    if (!cursor.climbed) visits += 1.0;
#if defined(BACKPROJECTION_FINISH_COARSE)
    steps_left -= 1.0;  // after this step
#endif
    if (!cursor.climbed && !minmax_window_empty(minmax_node_part(cursor, window))) {
      vec2 range = minmax_cursor_read(cursor);
      vec4 texels = minmax_node_texels(cursor);
      vec4 rect = backprojection_project(texels, range.x * INV_DEPTH_SCALE, query);
      // (A call inside && would be a branch: Shader Model 3 slots are counted.)
      bool touches = backprojection_touches(rect);
      if (range.x < limit && touches) {
        // Flat (one depth, every texel occluding): its texels tile one patch.
        // Level 0 always is (min == max), so it is never descended.
        bool one_patch = range.y < limit && range.x == range.y;
#if defined(BACKPROJECTION_FINISH_COARSE)
        descend = !one_patch && steps_left >= steps_to_end + 4.0;
        if (!descend) {
          state = backprojection_add_share(state, rect, range.y < limit ? 1.0 : 0.5);
        }
#else
        descend = !one_patch;
        if (one_patch) state = backprojection_add(state, rect);
#endif
      }
    }
    if (descend) {
      minmax_descend(cursor);
    } else {
      minmax_next(cursor);
    }
#if defined(BACKPROJECTION_FINISH_COARSE)
    steps_to_end += descend ? 4.0 : -1.0;
#endif
    // Stop when the light is covered or the work bound is reached. (A call
    // inside || would be a branch: Shader Model 3 slots are counted.)
    bool covered = backprojection_covered(state);
    cursor.done = cursor.done || covered || visits >= float(BACKPROJECTION_MAX_NODES);
  }
#endif
  return state;
}

// The normalized depth below which a texel occludes the receiver and lies
// in front of it. A texel occludes when d < reference; one at or behind
// the receiver (a negative bias lets it pass) cannot be projected towards
// the light (g(z) is infinite or negative) and is skipped, as the reference
// does. For the library's linear map DEPTH_SCALE is a power of two, so
// d < z_r DEPTH_SCALE is exactly z < z_r.
float backprojection_limit(vec3 query) {
  return min(shadow_normalized_reference(query.z), query.z * DEPTH_SCALE);
}

// Whether any texel can occlude the receiver; `limit` and `window` are then
// backprojection_walk()'s arguments.
bool backprojection_start(vec3 query, out float limit, out vec4 window) {
  limit = backprojection_limit(query);
  // The top node (1x1) holds the map's minimum: nothing nearer can occlude.
  float map_min = minmax_top_node().x;
  window = backprojection_window(query, map_min * INV_DEPTH_SCALE);
  // A call inside && would be a branch (Shader Model 3 slots are counted).
  bool empty = minmax_window_empty(window);
  return map_min < limit && !empty;
}

#endif
