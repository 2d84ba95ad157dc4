// Percentage-closer filtering over a Poisson disk: pcf_poisson itself and the
// last step of both PCSS variants, which differ only in how they find the
// radius. A receiver-plane slope in the query moves each sample's reference
// along the receiver's plane (zero for variants without the key).
#include "penumbra/reference/sampling.hpp"
#include "technique_parts.hpp"

namespace penumbra::reference::detail {

double poisson_pcf(const ShadowMapView& map, const Query& q, double z_ref,
                   const std::vector<Point2>& disk, double radius) {
  double sum = 0.0;
  for (const Point2& d : disk) {
    const double du = d[0] * radius;
    const double dv = d[1] * radius;
    sum += bilinear_compare(map, q.u + du, q.v + dv, z_ref + q.dz_du * du + q.dz_dv * dv);
  }
  return sum / double(disk.size());
}

}  // namespace penumbra::reference::detail
