// The checks of a variant's parts that check_variant() runs per technique
// (technique_table.cpp): what a variant read from index.json must carry.
#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "technique_parts.hpp"

namespace penumbra::reference::detail {
namespace {

// How far the float blur weights' sum may be from 1.
constexpr double kBlurWeightSumSlack = 1e-5;

Error bad_variant(const Variant& variant, std::string message) {
  return make_error(Error::Kind::bad_input, variant.name, std::move(message));
}

// A key with one value besides its default (unset): `value` is unset or `only`.
Status check_single_value(const Variant& variant, std::string_view key,
                          const std::optional<std::string>& value, std::string_view only) {
  if (value && *value != only) {
    return bad_variant(variant, std::string(key) + " is \"" + *value + "\" but must be \"" +
                                    std::string(only) + "\"");
  }
  return {};
}

}  // namespace

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
  return check_single_value(variant, "traversal", variant.keys.traversal, kBruteForceTraversal);
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

Status check_kernel(const Variant& variant, int max_kernel, bool odd) {
  const auto& kernel = variant.keys.kernel;
  if (!kernel || *kernel < 1 || *kernel > max_kernel || (odd && *kernel % 2 == 0)) {
    return bad_variant(variant, std::string(to_string(variant.technique)) + " needs " +
                                    (odd ? "an odd kernel" : "a kernel") + " from 1 to " +
                                    std::to_string(max_kernel));
  }
  return {};
}

Status check_max_nodes(const Variant& variant) {
  const auto& max_nodes = variant.keys.max_nodes;
  if (max_nodes && (*max_nodes < 1 || *max_nodes > kMaxMaxNodes)) {
    return bad_variant(variant, "max_nodes is " + std::to_string(*max_nodes) +
                                    " but must be from 1 to " + std::to_string(kMaxMaxNodes));
  }
  return {};
}

Status check_light_bits(const Variant& variant) {
  const auto& bits = variant.keys.light_bits;
  if (!bits || std::ranges::find(kAllowedLightBits, *bits) == kAllowedLightBits.end()) {
    return bad_variant(variant,
                       "bitmask_backprojection needs light_bits, one of " + allowed_light_bits());
  }
  return {};
}

// The only rotation besides the default (the baked set at every pixel).
Status check_rotation(const Variant& variant) {
  return check_single_value(variant, "rotation", variant.keys.rotation, kIgnRotation);
}

}  // namespace penumbra::reference::detail
