// The `receiver_plane` key's depth slope of a receiver (docs/techniques.md,
// "Receiver-plane depth bias").
#pragma once

#include <array>
#include <vector>

#include "penumbra/model/light.hpp"
#include "penumbra/support/image.hpp"

namespace penumbra::reference {

// A receiver at least this steep, in z per unit of distance across the
// light's view, has no plane, as the shader's PENUMBRA_MAX_PLANE_TANGENT.
inline constexpr double kMaxPlaneTangent = 10.0;

// (dz/du, dz/dv) from screen derivatives: the inverse of the 2x2 Jacobian
// of (u, v) times (dz/dx, dz/dy); (0, 0) where that is singular, not finite
// or either component is at least `max_slope`.
std::array<double, 2> depth_slope(double du_dx, double dv_dx, double dz_dx, double du_dy,
                                  double dv_dy, double dz_dy, double max_slope);

// kMaxPlaneTangent in z per unit of uv for a receiver at linear depth z.
double max_depth_slope(const LightParams& light, double z);

// The slopes a GPU may give pixel (i, j) of `receivers`: derivatives are
// differences within the pixel's 2x2 quad, taken in the pixel's own row and
// column (fine) or in the quad's other one (coarse: which is the
// implementation's choice), so four candidates.
std::vector<std::array<double, 2>> depth_slope_candidates(const FloatImage& receivers, int i, int j,
                                                          const LightParams& light);

}  // namespace penumbra::reference
