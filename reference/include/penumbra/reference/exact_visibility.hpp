// Exact area-light visibility for the test scenes: the ground truth that
// shadow-map techniques approximate (docs/verification.md, "Exact ground
// truth"). Independent of any shadow map.
#pragma once

#include "penumbra/reference/scene.hpp"
#include "penumbra/support/image.hpp"

namespace penumbra::reference {

// The fraction of the light square [-L, L]^2 at z = 0 seen from the
// light-view point (x, y, z): 1 - area(union of the occluders projected from
// the point onto z = 0, clipped to the light) / (2L)^2. Rectangles and boxes
// count where they are nearer the light than z - bias, the same rule as
// every shadow-map comparison (so custom_light's decal inside the bias casts
// none; a box reaching past that depth is cut there).
double exact_visibility(const Scene& scene, double x, double y, double z);

// exact_visibility() at each pixel of `receivers` (3 or 4 channels: u, v,
// z_r), at the point P = ((u - 0.5) Fw z_r / n, (v - 0.5) Fw z_r / n, z_r).
// 1 channel, the receivers' size.
FloatImage exact_visibility_image(const Scene& scene, const FloatImage& receivers);

// The scene as a shadow map can see it: every rectangle clipped to the map's
// frustum at its depth (|x|, |y| <= Fw z / (2 n)), those left empty dropped;
// boxes are kept whole (a scene's boxes lie inside the frustum).
// Where exact_visibility() of this scene and of the whole scene agree, a
// receiver's shadow depends on nothing outside the map.
Scene clipped_to_map(const Scene& scene);

}  // namespace penumbra::reference
