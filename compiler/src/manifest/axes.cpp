#include "manifest/axes.hpp"

#include <algorithm>
#include <cstddef>

#include "penumbra/compiler/disk.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/map_layout.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/support/text.hpp"

namespace penumbra::manifest_detail {
namespace {

// The largest odd kernel that fits kMaxSamples (pcf_grid's grid is centred).
constexpr int kMaxOddKernel = kMaxSamples % 2 == 1 ? kMaxSamples : kMaxSamples - 1;

// Reads one value or a list of values with `read_one`, appending to `out`
// those not already there: a repeated value is one value, so repeats do not
// multiply the set's product.
template <typename T, typename ReadOne>
Status read_list(const JsonNode& node, ReadOne read_one, std::vector<T>& out) {
  Result<std::vector<JsonNode>> items = node.items();
  if (!items) return items.error();
  for (const JsonNode& item : *items) {
    Result<T> value = read_one(item);
    if (!value) return value.error();
    if (std::ranges::find(out, *value) == out.end()) out.push_back(std::move(*value));
  }
  return {};
}

Result<Technique> read_technique(const JsonNode& node) {
  Result<std::string> name = node.string();
  if (!name) return name.error();
  if (auto technique = parse_technique(*name)) return *technique;
  return node.error("unknown technique '" + shorten(*name) +
                    "'; allowed techniques: " + allowed_techniques());
}

Result<Target> read_target(const JsonNode& node) {
  Result<std::string> name = node.string();
  if (!name) return name.error();
  if (auto target = parse_target(*name)) return *target;
  return node.error("unknown target '" + shorten(*name) +
                    "'; allowed targets: " + allowed_targets());
}

Result<Form> read_form(const JsonNode& node) {
  Result<std::string> name = node.string();
  if (!name) return name.error();
  if (auto form = parse_form(*name)) return *form;
  return node.error("unknown form '" + shorten(*name) + "'; allowed forms: " + allowed_forms());
}

Result<int> read_sample_count(const JsonNode& node) {
  Result<int> count = node.integer();
  if (!count) return count.error();
  if (Status status = check_sample_count(*count); !status) return node.error(status.error());
  return *count;
}

Result<int> read_kernel(const JsonNode& node) {
  Result<int> kernel = node.integer();
  if (!kernel) return kernel.error();
  if (*kernel >= 1 && *kernel <= kMaxSamples) return *kernel;
  return node.error("kernel " + std::to_string(*kernel) + " is out of range; allowed 1.." +
                    std::to_string(kMaxSamples) + " (pcf_grid: odd sizes 1.." +
                    std::to_string(kMaxOddKernel) + ")");
}

Result<std::string> read_traversal(const JsonNode& node) {
  Result<std::string> name = node.string();
  if (!name) return name.error();
  if (*name == kBruteForceTraversal) return name;
  return node.error("unknown traversal '" + shorten(*name) +
                    "'; allowed traversals: " + std::string(kBruteForceTraversal) +
                    " (leave the key out for the min-max traversal)");
}

Result<std::string> read_rotation(const JsonNode& node) {
  Result<std::string> name = node.string();
  if (!name) return name.error();
  if (*name == kIgnRotation) return name;
  return node.error("unknown rotation '" + shorten(*name) +
                    "'; allowed rotations: " + std::string(kIgnRotation) +
                    " (leave the key out for the same samples at every pixel)");
}

// A string that `parse` takes: `key`'s value names one of `allowed`
// (docs/techniques.md's `section` describes them).
template <typename Parse>
Result<std::string> read_named(const JsonNode& node, std::string_view key, Parse parse,
                               const std::string& allowed, std::string_view section) {
  Result<std::string> name = node.string();
  if (!name) return name.error();
  if (parse(*name)) return name;
  return node.error("unknown " + std::string(key) + " '" + shorten(*name) + "'; allowed " +
                    allowed + " (docs/techniques.md, \"" + std::string(section) + "\")");
}

Result<std::string> read_map_encoding(const JsonNode& node) {
  return read_named(node, "map_encoding", parse_map_encoding,
                    "map encodings: " + allowed_map_encodings(), "Map encodings");
}

Result<std::string> read_map_layout(const JsonNode& node) {
  return read_named(node, "map_layout", parse_map_layout, "map layouts: " + allowed_map_layouts(),
                    "Map layouts");
}

Result<int> read_max_nodes(const JsonNode& node) {
  Result<int> count = node.integer();
  if (!count) return count.error();
  if (*count >= 1 && *count <= kMaxMaxNodes) return *count;
  return node.error("max_nodes " + std::to_string(*count) + " is out of range; allowed 1.." +
                    std::to_string(kMaxMaxNodes));
}

Result<int> read_blur_radius(const JsonNode& node) {
  Result<int> radius = node.integer();
  if (!radius) return radius.error();
  if (*radius >= 1 && *radius <= kMaxBlurRadius) return *radius;
  return node.error("blur_radius " + std::to_string(*radius) + " is out of range; allowed 1.." +
                    std::to_string(kMaxBlurRadius));
}

Result<int> read_light_bits(const JsonNode& node) {
  Result<int> bits = node.integer();
  if (!bits) return bits.error();
  if (std::ranges::find(kAllowedLightBits, *bits) != kAllowedLightBits.end()) return *bits;
  return node.error("light_bits " + std::to_string(*bits) + " is not allowed; allowed " +
                    allowed_light_bits() + " (a square grid of light samples)");
}

// depth_aware and receiver_plane: JSON booleans.
Result<bool> read_flag(const JsonNode& node) {
  return node.boolean();
}

Result<std::string> read_disk(const JsonNode& node,
                              const std::map<std::string, DiskFamily>& disks) {
  Result<std::string> name = node.string();
  if (!name) return name.error();
  if (*name == kWhitepaperDisk || disks.contains(*name)) return name;
  std::string allowed;
  for (const auto& [declared, family] : disks) allowed += declared + ", ";
  return node.error("unknown disk '" + shorten(*name) + "'; allowed disks: " + allowed +
                    std::string(kWhitepaperDisk) + " (declare generated disks under /disks)");
}

}  // namespace

// Axis lists the keys in kVariantKeyNames order.
std::string_view axis_name(Axis axis) {
  return kVariantKeyNames[static_cast<std::size_t>(axis)];
}

bool uses(Technique technique, Axis axis) {
  return std::ranges::find(describe(technique).keys, axis_name(axis)) !=
         describe(technique).keys.end();
}

bool is_optional(Technique technique, Axis axis) {
  return std::ranges::find(describe(technique).optional_keys, axis_name(axis)) !=
         describe(technique).optional_keys.end();
}

bool is_given(const AxisValues& values, Axis axis) {
  switch (axis) {
    case Axis::kernel:
      return !values.kernel.empty();
    case Axis::blocker_samples:
      return !values.blocker_samples.empty();
    case Axis::pcf_samples:
      return !values.pcf_samples.empty();
    case Axis::disk:
      return !values.disk.empty();
    case Axis::traversal:
      return !values.traversal.empty();
    case Axis::max_nodes:
      return !values.max_nodes.empty();
    case Axis::blur_radius:
      return !values.blur_radius.empty();
    case Axis::depth_aware:
      return !values.depth_aware.empty();
    case Axis::light_bits:
      return !values.light_bits.empty();
    case Axis::rotation:
      return !values.rotation.empty();
    case Axis::receiver_plane:
      return !values.receiver_plane.empty();
    case Axis::map_encoding:
      return !values.map_encoding.empty();
    case Axis::map_layout:
      return !values.map_layout.empty();
  }
  return false;
}

std::string describe_axes(Technique technique) {
  std::string out;
  for (Axis axis : kKeyAxes) {
    if (!uses(technique, axis)) continue;
    if (!out.empty()) out += ", ";
    out += axis_name(axis);
    if (is_optional(technique, axis)) out += " (optional)";
  }
  return out.empty() ? "no keys" : out;
}

Status read_axes(const JsonNode& node, const std::map<std::string, DiskFamily>& disks,
                 AxisValues& out) {
  const auto read_disk_here = [&disks](const JsonNode& item) { return read_disk(item, disks); };
  if (node.has("technique")) {
    PENUMBRA_TRY(read_list(node.member("technique"), read_technique, out.technique));
  }
  if (node.has("blocker_samples")) {
    PENUMBRA_TRY(read_list(node.member("blocker_samples"), read_sample_count, out.blocker_samples));
  }
  if (node.has("pcf_samples")) {
    PENUMBRA_TRY(read_list(node.member("pcf_samples"), read_sample_count, out.pcf_samples));
  }
  if (node.has("kernel")) PENUMBRA_TRY(read_list(node.member("kernel"), read_kernel, out.kernel));
  if (node.has("disk")) PENUMBRA_TRY(read_list(node.member("disk"), read_disk_here, out.disk));
  if (node.has("traversal")) {
    PENUMBRA_TRY(read_list(node.member("traversal"), read_traversal, out.traversal));
  }
  if (node.has("max_nodes")) {
    PENUMBRA_TRY(read_list(node.member("max_nodes"), read_max_nodes, out.max_nodes));
  }
  if (node.has("blur_radius")) {
    PENUMBRA_TRY(read_list(node.member("blur_radius"), read_blur_radius, out.blur_radius));
  }
  if (node.has("depth_aware")) {
    PENUMBRA_TRY(read_list(node.member("depth_aware"), read_flag, out.depth_aware));
  }
  if (node.has("light_bits")) {
    PENUMBRA_TRY(read_list(node.member("light_bits"), read_light_bits, out.light_bits));
  }
  if (node.has("rotation")) {
    PENUMBRA_TRY(read_list(node.member("rotation"), read_rotation, out.rotation));
  }
  if (node.has("receiver_plane")) {
    PENUMBRA_TRY(read_list(node.member("receiver_plane"), read_flag, out.receiver_plane));
  }
  if (node.has("map_encoding")) {
    PENUMBRA_TRY(read_list(node.member("map_encoding"), read_map_encoding, out.map_encoding));
  }
  if (node.has("map_layout")) {
    PENUMBRA_TRY(read_list(node.member("map_layout"), read_map_layout, out.map_layout));
  }
  if (node.has("target")) PENUMBRA_TRY(read_targets(node.member("target"), out.target));
  return {};
}

Status check_kernels(const JsonNode& node, const AxisValues& axes) {
  const bool grid = std::ranges::find(axes.technique, Technique::pcf_grid) != axes.technique.end();
  if (!grid || !node.has("kernel")) return {};
  Result<std::vector<JsonNode>> items = node.member("kernel").items();
  if (!items) return items.error();
  for (const JsonNode& item : *items) {
    Result<int> value = item.integer();
    if (!value) return value.error();
    const int kernel = *value;
    if (kernel % 2 == 1 && kernel <= kMaxOddKernel) continue;
    return item.error("kernel " + std::to_string(kernel) +
                      " is not allowed for pcf_grid; allowed odd sizes 1.." +
                      std::to_string(kMaxOddKernel) + " (minmax_pcf takes any size 1.." +
                      std::to_string(kMaxSamples) + ")");
  }
  return {};
}

Status read_targets(const JsonNode& node, std::vector<Target>& out) {
  return read_list(node, read_target, out);
}

Status read_forms(const JsonNode& node, std::vector<Form>& out) {
  std::vector<Form> read;
  PENUMBRA_TRY(read_list(node, read_form, read));  // an empty list is an error
  out.clear();
  for (Form form : kAllForms) {
    if (std::ranges::find(read, form) != read.end()) out.push_back(form);
  }
  return {};
}

}  // namespace penumbra::manifest_detail
