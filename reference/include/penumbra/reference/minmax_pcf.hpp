// minmax_pcf (docs/techniques.md; Dmitriev 2007): the fraction of the
// K x K texel window around a receiver whose texels do not occlude it,
// computed in float exactly as a correct shader does.
#pragma once

#include <limits>

#include "penumbra/reference/minmax_mip.hpp"
#include "penumbra/reference/shadow_map.hpp"

namespace penumbra::reference {

// The K x K window: columns floor(u W) - floor(K / 2) .. + K - 1, rows
// likewise, with u W and v H formed in float. It may reach outside the map.
TexelRect minmax_pcf_window(const ShadowMapView& map, double u, double v, int kernel);

// The texels of `window` inside the map with depth < z_ref, one by one in
// rows, stopping after `max_texels` (a target's cap on the shader's steps).
long long count_occluders_brute_force(const ShadowMapView& map, const TexelRect& window,
                                      float z_ref,
                                      long long max_texels = std::numeric_limits<long long>::max());

// 1 - C / K^2 in the shader's arithmetic: exactly 1 for C = 0, else
// float(K * K - C) * minmax_pcf_inv_area(K), one correctly rounded product of
// exact operands (within one ulp, exactly 0 for C = K^2, bit-identical).
float minmax_pcf_visibility(long long count, int kernel);

}  // namespace penumbra::reference
