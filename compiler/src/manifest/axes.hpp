// The variant axes that sets and exclusions give, and which ones a technique
// uses (contract section 2).
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
inline constexpr std::array<std::string_view, 6> kAxisKeys = {
    "technique", "blocker_samples", "pcf_samples", "kernel", "disk", "target"};

// The keys a technique may need, in kVariantKeyNames order; every variant has
// targets.
enum class Axis { kernel, blocker_samples, pcf_samples, disk };
inline constexpr std::array kKeyAxes = {Axis::kernel, Axis::blocker_samples, Axis::pcf_samples,
                                        Axis::disk};

std::string_view axis_name(Axis axis);
// Whether `technique` needs the key; it ignores the keys it does not need.
bool uses(Technique technique, Axis axis);
bool is_given(const AxisValues& values, Axis axis);
// "blocker_samples, pcf_samples, disk", or "no keys" for hard.
std::string describe_axes(Technique technique);

// Reads the axis keys `node` gives into `out`, checking every value: names
// known, sample counts 1..kMaxSamples, kernels odd 1..kMaxSamples - 1, disks
// built in or declared in `disks`.
Status read_axes(const JsonNode& node, const std::map<std::string, DiskFamily>& disks,
                 AxisValues& out);

// One target name or a list of them, as in the manifest's "targets".
Status read_targets(const JsonNode& node, std::vector<Target>& out);

}  // namespace penumbra::manifest_detail
