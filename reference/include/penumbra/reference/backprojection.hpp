// backprojection (docs/techniques.md; Dmitriev 2007, after Guennebaud et al.
// 2006): every occluding texel is the patch of its frustum footprint at its
// depth; seen from the receiver point each patch projects onto the light
// plane, and the light's covered fraction is the sum of the projected areas
// inside the light. The reference sums texel by texel, in double.
#pragma once

#include "penumbra/reference/light.hpp"
#include "penumbra/reference/minmax_mip.hpp"
#include "penumbra/reference/shadow_map.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {

// The texels of the map whose patch can touch the light from receiver `q`
// when no texel is nearer the light than `min_depth` (exact culling; one
// texel of margin on each side). Empty when min_depth >= q.z.
TexelRect backprojection_window(const ShadowMapView& map, const LightParams& light, const Query& q,
                                double min_depth);

// S: the sum, over the texels of `texels` inside the map that occlude q
// (depth < float_reference(q.z, bias)) and lie in front of it (depth < q.z),
// of the area of the patch projected from q onto z = 0, clipped to the light.
double backprojected_area(const ShadowMapView& map, const LightParams& light, const Query& q,
                          const TexelRect& texels);

// max(0, 1 - S / (2L)^2).
double backprojection_visibility(double area, const LightParams& light);

}  // namespace penumbra::reference
