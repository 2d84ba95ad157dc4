// screen_blur's factor pass (the step-2 shader of the GameDev.net article
// "Soft-Edged Shadows"): a
// 3x3 point-compare PCF at whole-texel offsets. Each compare is hard's point
// sample, so the ambiguity rule is hard's, applied to all nine.
#include "technique_parts.hpp"

namespace penumbra::reference::detail {

Sample screen_blur_factor(const ShadowMapView& map, const Query& q, double z_ref,
                          const SamplingPrecision& precision) {
  double lit_count = 0.0;
  Ambiguity ambiguous = Ambiguity::none;
  for (int j = -1; j <= 1; ++j) {
    for (int i = -1; i <= 1; ++i) {
      const Sample s = point_compare(map, q.u + double(i) / map.width(),
                                     q.v + double(j) / map.height(), z_ref, precision);
      lit_count += s.visibility;
      ambiguous |= s.ambiguous;
    }
  }
  return {lit_count / 9.0, ambiguous};
}

}  // namespace penumbra::reference::detail
