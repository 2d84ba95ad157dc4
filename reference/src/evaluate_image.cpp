// Whole-image evaluation, with the input checks a CLI user's files need.
// Rows run in parallel (oneTBB): each pixel is its own evaluation, written
// to its own place, so the image is the same whatever the thread count.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
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

Status check_receivers(const FloatImage& receivers) {
  if ((receivers.channels != 3 && receivers.channels != 4) || receivers.pixel_count() == 0) {
    return make_error(Error::Kind::bad_input, "receivers",
                      "needs a non-empty 3- or 4-channel image (u, v, z_r), got " +
                          std::to_string(receivers.channels) + " channels");
  }
  return {};
}

Status check_inputs(const FloatImage& shadow_map, const FloatImage& receivers) {
  if (shadow_map.channels != 1 || shadow_map.pixel_count() == 0) {
    return make_error(Error::Kind::bad_input, "shadow map",
                      "needs a non-empty 1-channel image of depth, got " +
                          std::to_string(shadow_map.channels) + " channels");
  }
  return check_receivers(receivers);
}

// The min-max mip of `map`, for a technique whose reference reads one.
std::optional<MinMaxMip> mip_for(const Variant& variant, const ShadowMapView& map) {
  if (!reference_reads_mip(variant.technique)) return std::nullopt;
  return MinMaxMip(map);
}

// Evaluates pixels of `receivers` against `map` (and `mip`, built from it
// where the technique reads one), the inputs checked.
class PixelEvaluator {
 public:
  PixelEvaluator(const Variant& variant, const ShadowMapView& map, const MinMaxMip* mip,
                 const LightParams& light, const FloatImage& receivers,
                 const SamplingPrecision& precision, const ShaderLimits& limits)
      : variant_(variant),
        map_(map),
        mip_(mip),
        light_(light),
        receivers_(receivers),
        precision_(precision),
        limits_(limits),
        plane_(variant.keys.receiver_plane.value_or(false)),
        tol_(tolerance(variant.technique, precision)) {}

  Sample operator()(int i, int j) const {
    const Query query{receivers_.at(i, j, 0), receivers_.at(i, j, 1), receivers_.at(i, j, 2), i, j};
    const auto evaluate_at = [&](const Query& q) {
      return mip_ ? evaluate(variant_, map_, *mip_, light_, q, precision_, limits_)
                  : evaluate(variant_, map_, light_, q, precision_, limits_);
    };
    return plane_ ? with_depth_slope(evaluate_at, query, receivers_, i, j, light_, tol_)
                  : evaluate_at(query);
  }

 private:
  const Variant& variant_;
  const ShadowMapView& map_;
  const MinMaxMip* mip_;
  const LightParams& light_;
  const FloatImage& receivers_;
  const SamplingPrecision& precision_;
  const ShaderLimits& limits_;
  bool plane_;
  double tol_;
};

// Every receiver against `map`, the inputs checked.
ReferenceImage evaluate_view(const Variant& variant, const ShadowMapView& map,
                             const LightParams& light, const FloatImage& receivers,
                             const SamplingPrecision& precision, const ShaderLimits& limits) {
  // Built once for the image, and only for a technique whose reference reads it.
  const std::optional<MinMaxMip> mip = mip_for(variant, map);
  const PixelEvaluator sample_at(variant, map, mip ? &*mip : nullptr, light, receivers, precision,
                                 limits);
  ReferenceImage result{FloatImage(receivers.width, receivers.height, 1),
                        FloatImage(receivers.width, receivers.height, 1), FloatImage(),
                        FloatImage()};
  tbb::parallel_for(0, receivers.height, [&](int j) {
    for (int i = 0; i < receivers.width; ++i) {
      const Sample sample = sample_at(i, j);
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
    const auto values = {result.visibility.data[k], nearer.visibility.data[k],
                         farther.visibility.data[k]};
    result.low.data[k] = std::min(values);
    result.high.data[k] = std::max(values);
  }
  return result;
}

Result<std::vector<FloatImage>> evaluate_visibility(
    const Variant& variant, const ShadowMapView& map, const LightParams& light,
    std::span<const FloatImage> receivers, std::span<const std::size_t> pixels,
    const SamplingPrecision& precision, const ShaderLimits& limits) {
  PENUMBRA_TRY(check_variant(variant));
  if (map.width() == 0 || map.height() == 0) {
    return make_error(Error::Kind::bad_input, "shadow map", "needs a non-empty image of depth");
  }
  for (const FloatImage& image : receivers) {
    PENUMBRA_TRY(check_receivers(image));
    if (image.width != receivers[0].width || image.height != receivers[0].height) {
      return make_error(Error::Kind::bad_input, "receivers",
                        "every image must be " + std::to_string(receivers[0].width) + "x" +
                            std::to_string(receivers[0].height) + ", got " +
                            std::to_string(image.width) + "x" + std::to_string(image.height));
    }
  }
  const std::size_t count = receivers.empty() ? 0 : receivers[0].pixel_count();
  for (const std::size_t k : pixels) {
    if (k >= count) {
      return make_error(Error::Kind::bad_input, "pixels",
                        "index " + std::to_string(k) + " is outside the " + std::to_string(count) +
                            "-pixel receivers image");
    }
  }
  std::vector<FloatImage> out;
  for (const FloatImage& image : receivers) out.emplace_back(image.width, image.height, 1);
  if (pixels.empty() || receivers.empty()) return out;
  const std::optional<MinMaxMip> mip = mip_for(variant, map);
  std::vector<PixelEvaluator> evaluators;
  for (const FloatImage& image : receivers) {
    evaluators.emplace_back(variant, map, mip ? &*mip : nullptr, light, image, precision, limits);
  }
  // Every (image, pixel) pair in parallel, each written to its own place.
  const std::size_t width = std::size_t(receivers[0].width);
  tbb::parallel_for(std::size_t(0), receivers.size() * pixels.size(), [&](std::size_t n) {
    const std::size_t image = n / pixels.size();
    const std::size_t k = pixels[n % pixels.size()];
    out[image].data[k] = float(evaluators[image](int(k % width), int(k / width)).visibility);
  });
  return out;
}

}  // namespace penumbra::reference
