// Whole-image evaluation, with the input checks a CLI user's files need.
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {
namespace {

// How far the float blur weights' sum may be from 1.
constexpr double kBlurWeightSumSlack = 1e-5;

Error bad_variant(const Variant& variant, std::string message) {
  return make_error(Error::Kind::bad_input, variant.name, std::move(message));
}

Status check_disk(const Variant& variant, const std::optional<Disk>& disk, const char* role,
                  const std::optional<int>& samples, const char* samples_key) {
  if (!disk || disk->points.empty()) {
    return bad_variant(variant, std::string("needs a ") + role + " disk");
  }
  if (samples && std::size_t(*samples) != disk->points.size()) {
    return bad_variant(variant, std::string(samples_key) + " is " + std::to_string(*samples) +
                                    " but the " + role + " disk has " +
                                    std::to_string(disk->points.size()) + " points");
  }
  return {};
}

// The only traversal besides the default (the min-max mip) is a brute-force loop.
Status check_traversal(const Variant& variant) {
  const auto& traversal = variant.keys.traversal;
  if (traversal && *traversal != kBruteForceTraversal) {
    return bad_variant(variant, "traversal is \"" + *traversal + "\" but must be \"" +
                                    std::string(kBruteForceTraversal) + "\"");
  }
  return {};
}

// screen_blur's radius and baked weights: 2R + 1 positive, symmetric taps
// summing to 1 (float rounding of each tap moves the sum by far less).
Status check_blur(const Variant& variant) {
  const auto& radius = variant.keys.blur_radius;
  if (!radius || *radius < 1 || *radius > kMaxBlurRadius) {
    return bad_variant(
        variant, "screen_blur needs a blur_radius from 1 to " + std::to_string(kMaxBlurRadius));
  }
  const std::vector<float>& w = variant.blur_weights;
  if (w.size() != std::size_t(2 * *radius + 1)) {
    return bad_variant(variant, "blur_radius is " + std::to_string(*radius) + " but there are " +
                                    std::to_string(w.size()) + " blur weights, not " +
                                    std::to_string(2 * *radius + 1));
  }
  double sum = 0.0;
  for (std::size_t k = 0; k < w.size(); ++k) {
    if (!(w[k] > 0.0f)) return bad_variant(variant, "blur weights must be positive");
    if (w[k] != w[w.size() - 1 - k]) return bad_variant(variant, "blur weights must be symmetric");
    sum += w[k];
  }
  if (std::abs(sum - 1.0) > kBlurWeightSumSlack) {
    return bad_variant(variant, "blur weights sum to " + std::to_string(sum) + ", not 1");
  }
  return {};
}

}  // namespace

Status check_variant(const Variant& variant) {
  const VariantKeys& keys = variant.keys;
  switch (variant.technique) {
    case Technique::hard:
      return {};
    case Technique::pcf_grid:
      if (!keys.kernel || *keys.kernel < 1 || *keys.kernel % 2 == 0) {
        return bad_variant(variant, "pcf_grid needs an odd positive kernel");
      }
      return {};
    case Technique::pcf_poisson:
      return check_disk(variant, variant.pcf_disk, "pcf", keys.pcf_samples, "pcf_samples");
    case Technique::pcss:
      PENUMBRA_TRY(check_disk(variant, variant.blocker_disk, "blocker", keys.blocker_samples,
                              "blocker_samples"));
      return check_disk(variant, variant.pcf_disk, "pcf", keys.pcf_samples, "pcf_samples");
    case Technique::minmax_pcf:
      if (!keys.kernel || *keys.kernel < 1 || *keys.kernel > kMaxSamples) {
        return bad_variant(variant,
                           "minmax_pcf needs a kernel from 1 to " + std::to_string(kMaxSamples));
      }
      return check_traversal(variant);
    case Technique::backprojection:
      if (keys.max_nodes && (*keys.max_nodes < 1 || *keys.max_nodes > kMaxMaxNodes)) {
        return bad_variant(variant, "max_nodes is " + std::to_string(*keys.max_nodes) +
                                        " but must be from 1 to " + std::to_string(kMaxMaxNodes));
      }
      return check_traversal(variant);
    case Technique::pcss_minmax:
      return check_disk(variant, variant.pcf_disk, "pcf", keys.pcf_samples, "pcf_samples");
    case Technique::screen_blur:
      return check_blur(variant);
  }
  return bad_variant(variant, "unknown technique");
}

Result<ReferenceImage> evaluate_image(const Variant& variant, const FloatImage& shadow_map,
                                      const LightParams& light, const FloatImage& receivers,
                                      const SamplingPrecision& precision) {
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
      const Sample sample = mip ? evaluate(variant, map, *mip, light, query, precision)
                                : evaluate(variant, map, light, query, precision);
      result.visibility.at(i, j) = float(sample.visibility);
      result.ambiguous.at(i, j) = sample.ambiguous ? 1.0f : 0.0f;
    }
  }
  return result;
}

}  // namespace penumbra::reference
