// Whole-image evaluation, with the input checks a CLI user's files need.
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "penumbra/reference/techniques.hpp"
#include "technique_table.hpp"

namespace penumbra::reference {

Status check_variant(const Variant& variant) {
  return detail::reference_for(variant.technique).check(variant);
}

Result<ReferenceImage> evaluate_image(const Variant& variant, const FloatImage& shadow_map,
                                      const LightParams& light, const FloatImage& receivers,
                                      const SamplingPrecision& precision,
                                      const ShaderLimits& limits) {
  PENUMBRA_TRY(check_variant(variant));
  if (shadow_map.channels != 1 || shadow_map.pixel_count() == 0) {
    return make_error(Error::Kind::bad_input, "shadow map",
                      "needs a non-empty 1-channel image of linear z, got " +
                          std::to_string(shadow_map.channels) + " channels");
  }
  if ((receivers.channels != 3 && receivers.channels != 4) || receivers.pixel_count() == 0) {
    return make_error(Error::Kind::bad_input, "receivers",
                      "needs a non-empty 3- or 4-channel image (u, v, z_r), got " +
                          std::to_string(receivers.channels) + " channels");
  }

  const ShadowMapView map(shadow_map);
  // Built once for the image, and only for a technique whose reference reads it.
  std::optional<MinMaxMip> mip;
  if (reference_reads_mip(variant.technique)) mip.emplace(map);
  ReferenceImage result{FloatImage(receivers.width, receivers.height, 1),
                        FloatImage(receivers.width, receivers.height, 1)};
  for (int j = 0; j < receivers.height; ++j) {
    for (int i = 0; i < receivers.width; ++i) {
      const Query query{receivers.at(i, j, 0), receivers.at(i, j, 1), receivers.at(i, j, 2)};
      const Sample sample = mip ? evaluate(variant, map, *mip, light, query, precision, limits)
                                : evaluate(variant, map, light, query, precision, limits);
      result.visibility.at(i, j) = float(sample.visibility);
      result.ambiguous.at(i, j) = sample.ambiguous ? 1.0f : 0.0f;
    }
  }
  return result;
}

}  // namespace penumbra::reference
