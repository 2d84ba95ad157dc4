// The variant axes that sets and exclusions give, and which ones a technique
// uses (docs/techniques.md).
#pragma once

#include <array>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "manifest/json_node.hpp"
#include "penumbra/compiler/manifest.hpp"

namespace penumbra::manifest_detail {

// The keys of a set or an exclusion.
inline constexpr std::array<std::string_view, 15> kAxisKeys = {
    "technique", "blocker_samples", "pcf_samples",  "kernel",      "disk",
    "traversal", "max_nodes",       "blur_radius",  "depth_aware", "light_bits",
    "rotation",  "receiver_plane",  "map_encoding", "map_layout",  "target"};

// The keys a technique may take, in kVariantKeyNames order; every variant has
// targets.
enum class Axis {
  kernel,
  blocker_samples,
  pcf_samples,
  disk,
  traversal,
  max_nodes,
  blur_radius,
  depth_aware,
  light_bits,
  rotation,
  receiver_plane,
  map_encoding,
  map_layout
};
inline constexpr std::array kKeyAxes = {
    Axis::kernel,     Axis::blocker_samples, Axis::pcf_samples,    Axis::disk,
    Axis::traversal,  Axis::max_nodes,       Axis::blur_radius,    Axis::depth_aware,
    Axis::light_bits, Axis::rotation,        Axis::receiver_plane, Axis::map_encoding,
    Axis::map_layout};

std::string_view axis_name(Axis axis);
// Whether `technique` takes the key (its TechniqueDescription's keys); it
// ignores the keys it does not take.
bool uses(Technique technique, Axis axis);
// Whether a set may leave the key out for `technique` (its description's
// optional_keys: traversal, max_nodes, depth_aware, rotation,
// receiver_plane, map_encoding and map_layout have defaults).
bool is_optional(Technique technique, Axis axis);
bool is_given(const AxisValues& values, Axis axis);
// "blocker_samples, pcf_samples, disk", "kernel, traversal (optional)", or
// "no keys" for hard.
std::string describe_axes(Technique technique);

// Reads the axis keys `node` gives into `out`, checking every value: names
// known, sample counts 1..kMaxSamples, kernels 1..kMaxSamples (odd ones only
// for pcf_grid: check_kernels), disks built in or declared in `disks`,
// traversal kBruteForceTraversal, max_nodes 1..kMaxMaxNodes, blur_radius
// 1..kMaxBlurRadius, depth_aware true or false, light_bits in kAllowedLightBits,
// rotation kIgnRotation, receiver_plane true or false, map_encoding a
// MapEncoding's name, map_layout a MapLayout's.
Status read_axes(const JsonNode& node, const std::map<std::string, DiskFamily>& disks,
                 AxisValues& out);

// pcf_grid's kernels are odd, 1..kMaxSamples - 1: checks the values of
// `node`'s "kernel" when `techniques` include pcf_grid.
Status check_kernels(const JsonNode& node, const AxisValues& axes);

// One target name or a list of them, as in the manifest's "targets".
Status read_targets(const JsonNode& node, std::vector<Target>& out);

// One form name or a list of at least one, as in "forms"; `out` is
// replaced, in kAllForms order.
Status read_forms(const JsonNode& node, std::vector<Form>& out);

}  // namespace penumbra::manifest_detail
