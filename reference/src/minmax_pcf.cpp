// minmax_pcf's reference counts the window texel by texel: the semantics are
// the brute-force count, and the shader's mip traversal must equal it (tests
// prove the CPU traversal in minmax_traversal.cpp does). Where a target caps
// the walk's steps, the count is what the same walk reached. Every step is float
// arithmetic the GPU performs identically (a correctly rounded product, floor,
// exact integer counts below 2^24), so the tolerance is 0.
#include "penumbra/reference/minmax_pcf.hpp"

#include <algorithm>
#include <cmath>

#include "penumbra/reference/sampling.hpp"
#include "technique_parts.hpp"

namespace penumbra::reference {
namespace {

// floor(coord * size) in float; far outside the map it is held at +-2^24
// (still outside) so that the window's ends stay in int range.
int window_texel(double coord, int size) {
  constexpr float kFar = 16777216.0f;
  return int(std::clamp(std::floor(float(coord) * float(size)), -kFar, kFar));
}

}  // namespace

TexelRect minmax_pcf_window(const ShadowMapView& map, double u, double v, int kernel) {
  const int x0 = window_texel(u, map.width()) - kernel / 2;
  const int y0 = window_texel(v, map.height()) - kernel / 2;
  return {x0, y0, x0 + kernel - 1, y0 + kernel - 1};
}

long long count_occluders_brute_force(const ShadowMapView& map, const TexelRect& window,
                                      float z_ref, long long max_texels) {
  const TexelRect inside = clip(window, map.width(), map.height());
  long long count = 0;
  long long read = 0;
  for (int j = inside.y0; j <= inside.y1; ++j) {
    const double* depths = map.row(j);
    for (int i = inside.x0; i <= inside.x1 && read < max_texels; ++i, ++read) {
      if (float(depths[i]) < z_ref) ++count;
    }
  }
  return count;
}

float minmax_pcf_visibility(long long count, int kernel) {
  if (count == 0) return 1.0f;
  return float(kernel * kernel - count) * minmax_pcf_inv_area(kernel);
}

namespace detail {

Sample minmax_pcf(const ShadowMapView& map, const MinMaxMip& mip, const LightParams& light,
                  const Query& q, const VariantKeys& keys, std::optional<int> capped_steps) {
  const int kernel = keys.kernel.value();
  const TexelRect window = minmax_pcf_window(map, q.u, q.v, kernel);
  const float z_ref = float_reference(q.z, light.bias);
  long long count = 0;
  if (!capped_steps) {
    count = count_occluders_brute_force(map, window, z_ref);
  } else if (keys.traversal == kBruteForceTraversal) {
    count = count_occluders_brute_force(map, window, z_ref, *capped_steps);
  } else {
    count = count_occluders(mip, window, z_ref, *capped_steps).count;
  }
  return {minmax_pcf_visibility(count, kernel)};
}

}  // namespace detail
}  // namespace penumbra::reference
