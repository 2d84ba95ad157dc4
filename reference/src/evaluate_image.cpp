// Whole-image evaluation, with the input checks a CLI user's files need.
// Rows run in parallel (oneTBB): each pixel is its own evaluation, written
// to its own place, so the image is the same whatever the thread count.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "penumbra/reference/receiver_plane.hpp"
#include "penumbra/reference/techniques.hpp"
#include "technique_table.hpp"

namespace penumbra::reference {
namespace {

// A receiver_plane variant's receiver under every depth slope a GPU may
// derive for pixel (i, j): the first candidate's result, with every
// candidate's reasons and depth_slope where their results differ by more
// than `tol`.
template <typename Evaluate>
Sample with_depth_slope(Evaluate evaluate_at, const Query& query, const FloatImage& receivers,
                        int i, int j, const LightParams& light, double tol) {
  Sample first;
  double lo = 0.0, hi = 0.0;
  Ambiguity ambiguous = Ambiguity::none;
  bool any = false;
  for (const auto& [dz_du, dz_dv] : depth_slope_candidates(receivers, i, j, light)) {
    Query q = query;
    q.dz_du = dz_du;
    q.dz_dv = dz_dv;
    const Sample s = evaluate_at(q);
    if (!any) first = s;
    lo = any ? std::min(lo, s.visibility) : s.visibility;
    hi = any ? std::max(hi, s.visibility) : s.visibility;
    ambiguous |= s.ambiguous;
    any = true;
  }
  first.ambiguous = ambiguous | ambiguous_if(hi - lo > tol, Ambiguity::depth_slope);
  return first;
}

Status check_inputs(const FloatImage& shadow_map, const FloatImage& receivers) {
  if (shadow_map.channels != 1 || shadow_map.pixel_count() == 0) {
    return make_error(Error::Kind::bad_input, "shadow map",
                      "needs a non-empty 1-channel image of depth, got " +
                          std::to_string(shadow_map.channels) + " channels");
  }
  if ((receivers.channels != 3 && receivers.channels != 4) || receivers.pixel_count() == 0) {
    return make_error(Error::Kind::bad_input, "receivers",
                      "needs a non-empty 3- or 4-channel image (u, v, z_r), got " +
                          std::to_string(receivers.channels) + " channels");
  }
  return {};
}

// Every receiver against `map`, the inputs checked.
ReferenceImage evaluate_view(const Variant& variant, const ShadowMapView& map,
                             const LightParams& light, const FloatImage& receivers,
                             const SamplingPrecision& precision, const ShaderLimits& limits) {
  // Built once for the image, and only for a technique whose reference reads it.
  std::optional<MinMaxMip> mip;
  if (reference_reads_mip(variant.technique)) mip.emplace(map);
  const bool plane = variant.keys.receiver_plane.value_or(false);
  const double tol = tolerance(variant.technique, precision);
  ReferenceImage result{FloatImage(receivers.width, receivers.height, 1),
                        FloatImage(receivers.width, receivers.height, 1), FloatImage(),
                        FloatImage()};
  tbb::parallel_for(0, receivers.height, [&](int j) {
    for (int i = 0; i < receivers.width; ++i) {
      const Query query{receivers.at(i, j, 0), receivers.at(i, j, 1), receivers.at(i, j, 2), i, j};
      const auto evaluate_at = [&](const Query& q) {
        return mip ? evaluate(variant, map, *mip, light, q, precision, limits)
                   : evaluate(variant, map, light, q, precision, limits);
      };
      const Sample sample = plane
                                ? with_depth_slope(evaluate_at, query, receivers, i, j, light, tol)
                                : evaluate_at(query);
      result.visibility.at(i, j) = float(sample.visibility);
      result.ambiguous.at(i, j) = float(std::uint16_t(sample.ambiguous));
    }
  });
  result.low = result.high = result.visibility;
  return result;
}

}  // namespace

Status check_variant(const Variant& variant) {
  return detail::reference_for(variant.technique).check(variant);
}

Result<ReferenceImage> evaluate_image(const Variant& variant, const FloatImage& shadow_map,
                                      const LightParams& light, const FloatImage& receivers,
                                      const SamplingPrecision& precision,
                                      const ShaderLimits& limits) {
  PENUMBRA_TRY(check_variant(variant));
  PENUMBRA_TRY(check_inputs(shadow_map, receivers));
  return evaluate_view(variant, ShadowMapView(shadow_map), light, receivers, precision, limits);
}

Result<ReferenceImage> evaluate_image(const Variant& variant, const FloatImage& stored,
                                      const EncodedDepth& encoded, const LightParams& light,
                                      const FloatImage& receivers,
                                      const SamplingPrecision& precision,
                                      const ShaderLimits& limits) {
  PENUMBRA_TRY(check_variant(variant));
  PENUMBRA_TRY(check_inputs(stored, receivers));
  const auto at_shift = [&](int shift) {
    return evaluate_view(variant, ShadowMapView(stored, encoded, shift), light, receivers,
                         precision, limits);
  };
  ReferenceImage result = at_shift(0);
  const ReferenceImage nearer = at_shift(-1);
  const ReferenceImage farther = at_shift(+1);
  const double half_tolerance = 0.5 * tolerance(variant.technique, precision);
  for (std::size_t k = 0; k < result.visibility.data.size(); ++k) {
    const bool tie =
        std::abs(double(nearer.visibility.data[k]) - farther.visibility.data[k]) > half_tolerance;
    const auto reasons = Ambiguity(std::uint16_t(result.ambiguous.data[k])) |
                         ambiguous_if(tie, Ambiguity::depth_tie);
    result.ambiguous.data[k] = float(std::uint16_t(reasons));
    result.low.data[k] = std::min({result.low.data[k], nearer.low.data[k], farther.low.data[k]});
    result.high.data[k] =
        std::max({result.high.data[k], nearer.high.data[k], farther.high.data[k]});
  }
  return result;
}

Result<FloatImage> evaluate_visibility(const Variant& variant, const FloatImage& stored,
                                       const EncodedDepth& encoded, const LightParams& light,
                                       const FloatImage& receivers,
                                       const SamplingPrecision& precision,
                                       const ShaderLimits& limits) {
  PENUMBRA_TRY(check_variant(variant));
  PENUMBRA_TRY(check_inputs(stored, receivers));
  return evaluate_view(variant, ShadowMapView(stored, encoded), light, receivers, precision, limits)
      .visibility;
}

}  // namespace penumbra::reference
