// backprojection (docs/techniques.md; Dmitriev 2007, after Guennebaud et al.
// 2006): every occluding texel is the patch of its frustum footprint at its
// depth; seen from the receiver point each patch projects onto the light
// plane, and the light's covered fraction is the sum of the projected areas
// inside the light. The reference sums texel by texel, in double.
#pragma once

#include "penumbra/model/light.hpp"
#include "penumbra/reference/minmax_mip.hpp"
#include "penumbra/reference/shadow_map.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {

// The projection's geometry. A perspective map's texel edge at map
// coordinate u has slope a = (u - 0.5) Fw / n, and from a receiver of slope
// a_r at z_r a point at depth z lands on the light plane z = 0 at
// (a - a_r) g(z), g(z) = z z_r / (z_r - z). A directional light's
// (orthographic map) texel edge lies at x = (u - 0.5) Fw, and the direction
// from the receiver through it has slope (x - x_r) g(z), g(z) = 1 / (z_r - z):
// its light is the square [-L, L]^2 of slopes. g grows with z in both.
double backprojection_to_slope(const LightParams& light);
double backprojection_gain(const LightParams& light, double z, double z_receiver);
// How far in uv from the receiver a patch can touch the light when no
// texel is nearer the light than `min_depth`: L / g(min_depth), in uv.
double backprojection_reach(const LightParams& light, const Query& q, double min_depth);

// The texels of the map whose patch can touch the light from receiver `q`
// when no texel is nearer the light than `min_depth` (exact culling; one
// texel of margin on each side). Empty when min_depth >= q.z.
TexelRect backprojection_window(const ShadowMapView& map, const LightParams& light, const Query& q,
                                double min_depth);

// S: the sum, over the texels of `texels` inside the map that occlude q
// (depth < float_reference(q.z, bias)) and lie in front of it (depth < q.z),
// of the area of the patch projected from q onto z = 0 (a directional
// light's: into slopes), clipped to the light.
double backprojected_area(const ShadowMapView& map, const LightParams& light, const Query& q,
                          const TexelRect& texels);

// max(0, 1 - S / (2L)^2).
double backprojection_visibility(double area, const LightParams& light);

}  // namespace penumbra::reference
