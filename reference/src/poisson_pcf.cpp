// Percentage-closer filtering over a Poisson disk: pcf_poisson itself and the
// last step of both PCSS variants, which differ only in how they find the
// radius.
#include "penumbra/reference/sampling.hpp"
#include "technique_parts.hpp"

namespace penumbra::reference::detail {

double poisson_pcf(const ShadowMapView& map, const Query& q, double z_ref,
                   const std::vector<Point2>& disk, double radius) {
  double sum = 0.0;
  for (const Point2& d : disk) {
    sum += bilinear_compare(map, q.u + d[0] * radius, q.v + d[1] * radius, z_ref);
  }
  return sum / double(disk.size());
}

}  // namespace penumbra::reference::detail
