// The receiver-plane depth slope (Schuler 2006) of a receivers-image pixel,
// as the query pass computes it from dFdx and dFdy of (u, v, z_r).
#include "penumbra/reference/receiver_plane.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra::reference {
namespace {

struct Texel3 {
  double u, v, z;
};

Texel3 at(const FloatImage& receivers, int i, int j) {
  // A quad's helper pixel past the image reads the clamped edge.
  i = std::clamp(i, 0, receivers.width - 1);
  j = std::clamp(j, 0, receivers.height - 1);
  return {receivers.at(i, j, 0), receivers.at(i, j, 1), receivers.at(i, j, 2)};
}

Texel3 minus(const Texel3& a, const Texel3& b) {
  return {a.u - b.u, a.v - b.v, a.z - b.z};
}

}  // namespace

std::array<double, 2> depth_slope(double du_dx, double dv_dx, double dz_dx, double du_dy,
                                  double dv_dy, double dz_dy, double max_slope) {
  const double det = du_dx * dv_dy - du_dy * dv_dx;
  const double scaled_u = dv_dy * dz_dx - dv_dx * dz_dy;
  const double scaled_v = du_dx * dz_dy - du_dy * dz_dx;
  // Tested before dividing, as the shader: a singular quad has no plane;
  // `!(<)` also takes NaN.
  const double bound = max_slope * std::abs(det);
  if (!(std::abs(scaled_u) < bound) || !(std::abs(scaled_v) < bound)) return {0, 0};
  return {scaled_u / det, scaled_v / det};
}

double max_depth_slope(const LightParams& light, double z) {
  // One unit of u or v spans Fw z / n across the light's view at depth z
  // (Fw at every depth, orthographic).
  return kMaxPlaneTangent * light.frustum_width *
         (light.orthographic() ? 1.0 : z / light.near_plane);
}

std::vector<std::array<double, 2>> depth_slope_candidates(const FloatImage& receivers, int i, int j,
                                                          const LightParams& light) {
  const double max_slope = max_depth_slope(light, at(receivers, i, j).z);
  const int x0 = i & ~1;
  const int y0 = j & ~1;
  std::vector<std::array<double, 2>> out;
  for (int row : {y0, y0 + 1}) {
    const Texel3 dx = minus(at(receivers, x0 + 1, row), at(receivers, x0, row));
    for (int column : {x0, x0 + 1}) {
      const Texel3 dy = minus(at(receivers, column, y0 + 1), at(receivers, column, y0));
      out.push_back(depth_slope(dx.u, dx.v, dx.z, dy.u, dy.v, dy.z, max_slope));
    }
  }
  return out;
}

}  // namespace penumbra::reference
