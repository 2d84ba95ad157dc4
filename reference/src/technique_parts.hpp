// The per-technique references that evaluate() (techniques.cpp) dispatches
// to, each in its own file, and the PCF step several of them share.
#pragma once

#include <vector>

#include "penumbra/reference/light.hpp"
#include "penumbra/reference/minmax_mip.hpp"
#include "penumbra/reference/precision.hpp"
#include "penumbra/reference/shadow_map.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference::detail {

// The mean of bilinear comparisons at uv + d * radius over the disk's points
// (pcf_poisson, and step 3 of pcss and pcss_minmax).
double poisson_pcf(const ShadowMapView& map, const Query& q, double z_ref,
                   const std::vector<Point2>& disk, double radius);

Sample minmax_pcf(const ShadowMapView& map, const LightParams& light, const Query& q, int kernel);

Sample backprojection(const ShadowMapView& map, const MinMaxMip& mip, const LightParams& light,
                      const Query& q);

Sample pcss_minmax(const ShadowMapView& map, const MinMaxMip& mip, const LightParams& light,
                   const Query& q, const Disk& pcf_disk, const SamplingPrecision& precision);

}  // namespace penumbra::reference::detail
