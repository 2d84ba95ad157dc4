#include "penumbra/model/model.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "penumbra/model/shader_contract.hpp"
#include "penumbra/model/target_traits.hpp"

namespace penumbra {

std::string_view to_string(Technique technique) {
  return describe(technique).name;
}

std::string_view to_string(Target target) {
  return traits(target).name;
}

std::optional<Technique> parse_technique(std::string_view name) {
  for (Technique technique : kAllTechniques) {
    if (describe(technique).name == name) return technique;
  }
  return std::nullopt;
}

std::optional<Target> parse_target(std::string_view name) {
  for (Target target : kAllTargets) {
    if (traits(target).name == name) return target;
  }
  return std::nullopt;
}

std::string allowed_techniques() {
  std::string out;
  for (Technique technique : kAllTechniques) {
    out += (out.empty() ? "" : ", ") + std::string(describe(technique).name);
  }
  return out;
}

SampleShape sample_shape(std::string_view method) {
  return method == kSquareStratified || method == kSquareR2 ? SampleShape::square
                                                            : SampleShape::disk;
}

std::string allowed_light_bits() {
  std::string out;
  for (int bits : kAllowedLightBits) out += (out.empty() ? "" : ", ") + std::to_string(bits);
  return out;
}

int light_grid_side(int light_bits) {
  int side = 1;
  while (side * side < light_bits) ++side;
  return side;
}

std::string allowed_targets() {
  std::string out;
  for (Target target : kAllTargets) {
    out += (out.empty() ? "" : ", ") + std::string(traits(target).name);
  }
  return out;
}

bool uses_minmax_mip(Technique technique) {
  return describe(technique).reads_minmax;
}

// The walk visits the 4 roots and the 4 children of every node it descends.
// It descends only nodes at levels 1..s that intersect the window, where the
// start level s is at most the smallest l with 2^l >= K - 1 (the window
// then spans at most two nodes per axis). A window of K texels meets at most
// floor((K - 1) / 2^l) + 2 nodes of level l per axis.
int minmax_max_visits(int kernel) {
  int visits = 4;
  for (int span = 2; span / 2 < kernel - 1; span *= 2) {
    const int per_axis = (kernel - 1) / span + 2;
    visits += 4 * per_axis * per_axis;
  }
  return visits;
}

int minmax_max_steps(int kernel) {
  const int visits = minmax_max_visits(kernel);
  return visits + (visits - 4) / 4;
}

std::optional<int> walk_step_bound(const Variant& variant, int limit) {
  const bool brute_force = variant.keys.traversal == kBruteForceTraversal;
  std::optional<int> own;
  if (variant.technique == Technique::minmax_pcf && variant.keys.kernel) {
    // Brute force reads a texel a step.
    const int kernel = *variant.keys.kernel;
    own = brute_force ? kernel * kernel : minmax_max_steps(kernel);
  }
  if (walks_backprojection(variant.technique)) {
    // A walk steps at most twice per visit (a visit, and the rise from the
    // children of a visited node); brute force reads a texel a step.
    const int nodes = variant.keys.max_nodes.value_or(kDefaultMaxNodes);
    own = brute_force ? nodes : 2 * nodes;
  }
  if (own && limit > 0) own = std::min(*own, limit);
  return own;
}

std::string inexact_walk(const Variant& variant, Target target) {
  const int limit = traits(target).walk_step_limit;
  const std::optional<int> steps = walk_step_bound(variant);
  if (variant.technique != Technique::minmax_pcf || limit <= 0 || !steps || *steps <= limit) {
    return {};
  }
  // The worst case grows with the kernel.
  Variant smaller = variant;
  int fits = 0;
  for (int kernel = 1; kernel <= kMaxSamples; ++kernel) {
    smaller.keys.kernel = kernel;
    if (*walk_step_bound(smaller) <= limit) fits = kernel;
  }
  const bool brute_force = variant.keys.traversal == kBruteForceTraversal;
  const std::string name(to_string(target));
  return variant.name + " cannot count exactly on " + name + ": its walk may take " +
         std::to_string(*steps) + " steps" + (brute_force ? " (a texel each)" : "") + ", and " +
         name + " stops every walk after " + std::to_string(limit) +
         " (ps_3_0 guarantees only 65,535 executed instructions); the largest kernel that fits " +
         "is " + std::to_string(fits) + (brute_force ? " with traversal brute_force" : "");
}

bool walks_backprojection(Technique technique) {
  return technique == Technique::backprojection || technique == Technique::bitmask_backprojection;
}

std::vector<float> gaussian_weights(int radius) {
  const double sigma = radius / 2.0;
  std::vector<double> exact;
  double sum = 0.0;
  for (int k = -radius; k <= radius; ++k) {
    exact.push_back(std::exp(-double(k) * k / (2.0 * sigma * sigma)));
    sum += exact.back();
  }
  std::vector<float> out;
  for (double w : exact) out.push_back(static_cast<float>(w / sum));
  return out;
}

// Keys are appended in a fixed order (k, b, p, disk, traversal, n, r,
// depth_aware, bits, rotation, receiver_plane, map_encoding, map_layout) and
// only when set (the flags only when true), so the name is total over any
// VariantKeys and stays stable across runs.
std::string variant_name(Technique technique, const VariantKeys& keys) {
  std::string name(to_string(technique));
  if (keys.kernel) name += "_k" + std::to_string(*keys.kernel);
  if (keys.blocker_samples) name += "_b" + std::to_string(*keys.blocker_samples);
  if (keys.pcf_samples) name += "_p" + std::to_string(*keys.pcf_samples);
  if (keys.disk) name += "_" + *keys.disk;
  if (keys.traversal) name += "_" + *keys.traversal;
  if (keys.max_nodes) name += "_n" + std::to_string(*keys.max_nodes);
  if (keys.blur_radius) name += "_r" + std::to_string(*keys.blur_radius);
  if (keys.depth_aware.value_or(false)) name += "_depth_aware";
  if (keys.light_bits) name += "_bits" + std::to_string(*keys.light_bits);
  if (keys.rotation) name += "_" + *keys.rotation;
  if (keys.receiver_plane.value_or(false)) name += "_receiver_plane";
  if (keys.map_encoding) name += "_" + *keys.map_encoding;
  if (keys.map_layout) name += "_" + *keys.map_layout;
  return name;
}

bool variant_less(const Variant& a, const Variant& b) {
  const auto key = [](const Variant& v) {
    const VariantKeys& k = v.keys;
    return std::tie(v.technique, k.kernel, k.blocker_samples, k.pcf_samples, k.disk, k.traversal,
                    k.max_nodes, k.blur_radius, k.depth_aware, k.light_bits, k.rotation,
                    k.receiver_plane, k.map_encoding, k.map_layout);
  };
  return key(a) < key(b);
}

}  // namespace penumbra
