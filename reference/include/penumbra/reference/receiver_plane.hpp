// The `receiver_plane` key's depth slope of a receiver (docs/techniques.md,
// "Receiver-plane depth bias").
#pragma once

#include <array>
#include <vector>

#include "penumbra/support/image.hpp"

namespace penumbra::reference {

// Slopes at or beyond this (z per unit of uv) are taken as no plane, as the
// shader's PENUMBRA_MAX_DEPTH_SLOPE.
inline constexpr double kMaxDepthSlope = 1e6;

// (dz/du, dz/dv) from screen derivatives: the inverse of the 2x2 Jacobian
// of (u, v) times (dz/dx, dz/dy); (0, 0) where that is singular, not finite
// or at least kMaxDepthSlope.
std::array<double, 2> depth_slope(double du_dx, double dv_dx, double dz_dx, double du_dy,
                                  double dv_dy, double dz_dy);

// The slopes a GPU may give pixel (i, j) of `receivers`: derivatives are
// differences within the pixel's 2x2 quad, taken in the pixel's own row and
// column (fine) or in the quad's other one (coarse: which is the
// implementation's choice), so four candidates.
std::vector<std::array<double, 2>> depth_slope_candidates(const FloatImage& receivers, int i,
                                                          int j);

}  // namespace penumbra::reference
