// Whole-image evaluation, with the input checks a CLI user's files need.
#include <optional>
#include <string>
#include <utility>

#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference {
namespace {

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
