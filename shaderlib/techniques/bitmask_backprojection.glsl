// bitmask_backprojection: "Bitmask Soft Shadows" (Schwarz & Stamminger 2007).
// The light [-L, L]^2 is sampled by N = LIGHT_GRID^2 points, one bit each:
// bit c of rows[r] is the sample at (c G + r + 0.5, r G + c + 0.5) / N of
// the light's side from its corner -L (G = LIGHT_GRID), the Hammersley
// point set in base G: every axis sees N distinct coordinates, so an
// axis-aligned patch edge moves the covered fraction in steps of 1 / N, not
// 1 / G as a regular grid's would. Every occluding patch back-projected onto
// the light plane (common/backprojection_walk.glsl) sets the bits of the
// samples it covers, and visibility = 1 - set bits / N. A sample covered
// twice is one bit, so overlapping occluders are not counted twice, as
// backprojection's sum does.

struct BackprojectionState {
  uint rows[LIGHT_GRID];
  int set;  // bits set so far
};

// Bits set in x. GLSL 3.30, ESSL 3.00 and Shader Model 4.0 have no bitCount.
int bitmask_popcount(uint x) {
  x = x - ((x >> 1u) & 0x55555555u);
  x = (x & 0x33333333u) + ((x >> 2u) & 0x33333333u);
  x = (x + (x >> 4u)) & 0x0F0F0F0Fu;
  return int((x * 0x01010101u) >> 24u);
}

// How far, in units of 1 / N of the light's side, each patch reaches past
// its edges. Two patches that share an edge compute it in different lanes
// (x1 of one, x0 of the other), which a compiler may evaluate differently
// where nothing is `precise` (GLSL 3.30 and ESSL 3.00 have none); so
// overlapped, a sample on the edge stays in one of them wherever the lanes
// differ by less than the margin (docs/verification.md, "Evaluations a
// compiler may choose"). A power of two: the offsets are exact.
#define BITMASK_EDGE_MARGIN 0.0625

// `state` with the bits of the samples inside a light-plane rectangle set.
BackprojectionState backprojection_add(BackprojectionState state, vec4 rect) {
  // The rectangle in units of 1 / N of the light's side, less the samples'
  // half unit (sample (c, r) sits at (c G + r, r G + c)), widened by the
  // margin.
  float g = float(LIGHT_GRID);
  vec4 t = (rect + LIGHT_WORLD_SIZE) * (g * g / (2.0 * LIGHT_WORLD_SIZE)) -
           vec4(vec2(0.5 + BITMASK_EDGE_MARGIN), vec2(0.5 - BITMASK_EDGE_MARGIN));
  // The rows with a sample whose y, r G + c, can lie in [t.y, t.w]; clamped
  // before the conversion: a far patch's index does not fit an int.
  int first_row = int(clamp(ceil((t.y - (g - 1.0)) / g), 0.0, g));
  int last_row = int(clamp(floor(t.w / g), -1.0, g - 1.0));
  PENUMBRA_LOOP for (int r = first_row; r <= last_row; ++r) {
    float row = float(r);
    // The columns c whose x, c G + r, lies in [t.x, t.z] and whose y does.
    float first = max(ceil((t.x - row) / g), ceil(t.y - row * g));
    float last = min(floor((t.z - row) / g), floor(t.w - row * g));
    first = clamp(first, 0.0, g);
    last = clamp(last, -1.0, g - 1.0);
    if (first > last) continue;
    // Bits first..last; 2u << 31u is 0, so last = 31 wraps to the top bits.
    uint mask = (2u << uint(last)) - (1u << uint(first));
    uint fresh = mask & ~state.rows[r];
    state.rows[r] |= fresh;
    state.set += bitmask_popcount(fresh);
  }
  return state;
}

bool backprojection_covered(BackprojectionState state) {
  return state.set >= LIGHT_GRID * LIGHT_GRID;
}

#include "common/backprojection_walk.glsl"

float shadow_visibility(vec3 query) {
  if (!(LIGHT_WORLD_SIZE > 0.0)) return shadow_compare_point(query.xy, query.z);
  float limit;
  vec4 window;
  if (!backprojection_start(query, limit, window)) return 1.0;
  BackprojectionState state;
  PENUMBRA_LOOP for (int r = 0; r < LIGHT_GRID; ++r) state.rows[r] = 0u;
  state.set = 0;
  state = backprojection_walk(query, window, limit, state);
  // N is a power of two: the quotient is exact.
  return 1.0 - float(state.set) / float(LIGHT_GRID * LIGHT_GRID);
}
