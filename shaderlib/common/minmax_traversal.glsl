// Depth-first walk of the min-max hierarchy over a texel window (Dmitriev 2007),
// shared by minmax_pcf, backprojection and pcss_minmax. Node coordinates are
// floats holding exact integers: Direct3D 9 has no integer bit operations.
// No recursion, arrays or stack (ps_3_0 cannot index temporaries): the
// cursor finds the next node from the current one alone.
#ifndef PENUMBRA_MINMAX_TRAVERSAL_GLSL
#define PENUMBRA_MINMAX_TRAVERSAL_GLSL

#include "common/minmax_mip.glsl"

// Hierarchy levels a map may have: 16 covers maps up to 65536 texels a side.
#define MINMAX_MAX_LEVEL 16

// Runs the statement that follows up to `bound` times (bound <= 255^3) or
// until `done`: three nested loops, none over 255 iterations, because a
// ps_3_0 loop counter stops at 255. all() tests both conditions without the
// branches of a short-circuit &&. Every loop of the walk is PENUMBRA_LOOP
// (HLSL [loop]): Direct3D compilers that unroll it take minutes.
#define MINMAX_LOOP_INNER(bound) ((bound) < 255 ? (bound) : 255)
#define MINMAX_LOOP_MIDDLE(bound) (((bound) + 254) / 255 < 255 ? ((bound) + 254) / 255 : 255)
#define MINMAX_LOOP_OUTER(bound) (((bound) + 65024) / 65025)
#define MINMAX_LOOP_WHILE(counter, count, done) all(bvec2((counter) < (count), !(done)))
#define MINMAX_FOR_BOUNDED(bound, done)                                                       \
  PENUMBRA_LOOP for (int loop_outer = 0; MINMAX_LOOP_WHILE(loop_outer, MINMAX_LOOP_OUTER(bound), done);    \
       ++loop_outer)                                                                          \
    PENUMBRA_LOOP for (int loop_middle = 0; MINMAX_LOOP_WHILE(loop_middle, MINMAX_LOOP_MIDDLE(bound), done); \
         ++loop_middle)                                                                       \
      PENUMBRA_LOOP for (int loop_inner = 0; MINMAX_LOOP_WHILE(loop_inner, MINMAX_LOOP_INNER(bound), done);  \
           ++loop_inner)
// One loop, where the bound fits one (a target's cap: hlsl_dx9): the outer
// two would run once, and vkd3d-compiler's ps_3_0 code spends about 14
// slots on each loop's counter and exit.
#define MINMAX_FOR_ONE_LOOP(bound, done) \
  PENUMBRA_LOOP for (int loop_inner = 0; MINMAX_LOOP_WHILE(loop_inner, bound, done); ++loop_inner)

struct MinmaxCursor {
  vec2 node;        // the current node at `level`
  float level;      // 0: map texels
  float span;       // 2^level: texels per node side
  vec2 first_root;  // the 2x2 roots start here, at level `start`
  float start;
  bool climbed;  // risen to a parent whose subtree is done: the next step moves past it
  bool done;
};

// Texel columns/rows [first, last] clipped to the map: (x0, y0, x1, y1);
// empty when x0 > x1 or y0 > y1.
vec4 minmax_clip_window(vec2 first, vec2 last) {
  return vec4(max(first, vec2(0.0)), min(last, MAP_SIZE - 1.0));
}

bool minmax_window_empty(vec4 window) {
  return any(greaterThan(window.xy, window.zw));
}

// The smallest level at which `window` meets at most `nodes` nodes per axis.
float minmax_level_spanning(vec4 window, float nodes) {
  float level = 0.0;
  float inv_span = 1.0;  // 2^-level, exact
  PENUMBRA_LOOP for (int k = 0; k < MINMAX_MAX_LEVEL; ++k) {
    vec2 spanned = floor(window.zw * inv_span) - floor(window.xy * inv_span);
    if (max(spanned.x, spanned.y) < nodes) break;
    level += 1.0;
    inv_span *= 0.5;
  }
  return level;
}

// The cursor on the first of the 2x2 roots: at the smallest level s where
// the window spans at most two nodes per axis.
MinmaxCursor minmax_begin(vec4 window) {
  MinmaxCursor cursor;
  cursor.level = minmax_level_spanning(window, 2.0);
  cursor.span = exp2(cursor.level);  // exact for an integer level
  cursor.start = cursor.level;
  cursor.first_root = floor(window.xy / cursor.span);
  cursor.node = cursor.first_root;
  cursor.climbed = false;
  cursor.done = false;
  return cursor;
}

// Texels of the cursor's node, clipped to the map: (x0, y0, x1, y1).
vec4 minmax_node_texels(MinmaxCursor cursor) {
  vec2 first = cursor.node * cursor.span;
  return minmax_clip_window(first, first + cursor.span - 1.0);
}

// The node's texels inside `window` (itself inside the map); empty when the
// node misses the window.
vec4 minmax_node_part(MinmaxCursor cursor, vec4 window) {
  vec2 first = cursor.node * cursor.span;
  return vec4(max(first, window.xy), min(first + cursor.span - 1.0, window.zw));
}

float minmax_texel_count(vec4 part) {
  return (part.z - part.x + 1.0) * (part.w - part.y + 1.0);
}

// (min, max) normalized depth of the cursor's node.
vec2 minmax_cursor_read(MinmaxCursor cursor) {
  return minmax_node(cursor.level, cursor.node);
}

// To the node's first child, (2i, 2j) at the level below.
void minmax_descend(inout MinmaxCursor cursor) {
  cursor.node *= 2.0;
  cursor.level -= 1.0;
  cursor.span *= 0.5;
}

// One step past the node's subtree: to its next sibling in the order
// (2i, 2j), (2i+1, 2j), (2i, 2j+1), (2i+1, 2j+1) (the roots likewise from
// first_root), or up to the parent when the node is the last of its
// siblings (`climbed`: the next step moves past the parent); done after the
// last root. One level a step, not a loop to the next sibling: every step
// of a walk then costs at most one loop body, which bounds its executed
// instructions (Shader Model 3 guarantees only 65,535).
void minmax_next(inout MinmaxCursor cursor) {
  bool root = cursor.level >= cursor.start;
  vec2 first_sibling = root ? cursor.first_root : floor(cursor.node * 0.5) * 2.0;
  vec2 offset = cursor.node - first_sibling;
  cursor.climbed = false;
  if (offset.x < 0.5) {
    cursor.node.x += 1.0;
  } else if (offset.y < 0.5) {
    cursor.node = vec2(first_sibling.x, cursor.node.y + 1.0);
  } else if (root) {
    cursor.done = true;
  } else {
    cursor.node = floor(cursor.node * 0.5);
    cursor.level += 1.0;
    cursor.span *= 2.0;
    cursor.climbed = true;
  }
}

#endif
