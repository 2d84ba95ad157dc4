#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "manifest/axes.hpp"
#include "manifest/sections.hpp"
#include "penumbra/model/map_layout.hpp"
#include "penumbra/model/shader_contract.hpp"
#include "penumbra/support/text.hpp"

namespace penumbra::manifest_detail {
namespace {

// "key 'K' is used by none of this set's techniques", why not where the
// model says, and the techniques that use it.
std::string unused_key(const AxisValues& axes, Axis axis) {
  std::string out =
      "key '" + std::string(axis_name(axis)) + "' is used by none of this set's techniques";
  if (axis == Axis::map_layout) {
    for (Technique technique : axes.technique) {
      const std::string why = layouts_refused(technique);
      if (!why.empty()) out += " (" + why + ")";
    }
  }
  std::string users;
  for (Technique technique : kAllTechniques) {
    if (!uses(technique, axis)) continue;
    users += (users.empty() ? "" : ", ") + std::string(to_string(technique));
  }
  return out + "; techniques that use it: " + users;
}

// Every technique has the keys it needs, and every key given is used by one of
// them (a key nobody uses is most likely a mistake).
Status check_set_keys(const JsonNode& node, const AxisValues& axes) {
  if (axes.technique.empty()) {
    return node.error("missing key 'technique'; allowed techniques: " + allowed_techniques());
  }
  for (Axis axis : kKeyAxes) {
    const std::string key(axis_name(axis));
    const bool given = is_given(axes, axis);
    bool used = false;
    for (Technique technique : axes.technique) {
      used = used || uses(technique, axis);
      if (!given && !is_optional(technique, axis) && uses(technique, axis)) {
        const std::string name(to_string(technique));
        return node.error("technique " + name + " needs key '" + key + "'; " + name + " uses " +
                          describe_axes(technique));
      }
    }
    if (given && !used) return node.member(key).error(unused_key(axes, axis));
  }
  return {};
}

// "spirv, glsl450, ..." for the targets `technique` can be emitted for.
std::string emittable_targets(Technique technique) {
  std::string out;
  for (Target target : kAllTargets) {
    if (can_emit(technique, target)) {
      out += (out.empty() ? "" : ", ") + std::string(to_string(target));
    }
  }
  return out;
}

// A technique whose shader keeps integer bits cannot be emitted for a target
// without integers (hlsl_dx9): the set is refused, naming where its targets
// came from, rather than a target silently dropped.
Status check_set_targets(const JsonNode& node, const AxisValues& axes) {
  for (Technique technique : axes.technique) {
    for (Target target : axes.target) {
      if (can_emit(technique, target)) continue;
      const std::string what = "technique " + std::string(to_string(technique)) +
                               " cannot be emitted for " + std::string(to_string(target)) +
                               " (Shader Model 3 has no integer bit operations); allowed " +
                               "targets: " + emittable_targets(technique);
      if (node.has("target")) return node.member("target").error(what);
      return node.error(what + " (this set takes the top-level targets; give it a 'target' list)");
    }
  }
  return {};
}

// minmax_pcf promises the exact count: a set whose kernel's worst-case walk
// exceeds a target's step cap (hlsl_dx9) is refused, like the integer
// techniques above, rather than built inexact or dropped silently.
Status check_set_exact(const JsonNode& node, const AxisValues& axes) {
  if (std::ranges::find(axes.technique, Technique::minmax_pcf) == axes.technique.end()) return {};
  std::vector<std::optional<std::string>> traversals(axes.traversal.begin(), axes.traversal.end());
  if (traversals.empty()) traversals.emplace_back();  // the min-max traversal
  for (int kernel : axes.kernel) {
    for (const std::optional<std::string>& traversal : traversals) {
      Variant variant;
      variant.technique = Technique::minmax_pcf;
      variant.keys.kernel = kernel;
      variant.keys.traversal = traversal;
      variant.name = variant_name(variant.technique, variant.keys);
      for (Target target : axes.target) {
        const std::string why = inexact_walk(variant, target);
        if (why.empty()) continue;
        const std::string fix = " or use a smaller kernel (docs/targets.md)";
        if (node.has("target")) {
          return node.member("target").error(why + "; leave " + std::string(to_string(target)) +
                                             " out of this set's 'target' list," + fix);
        }
        return node.error(why + "; this set takes the top-level targets: give it a 'target' " +
                          "list without " + std::string(to_string(target)) + "," + fix);
      }
    }
  }
  return {};
}

// A map layout a target cannot read (array on hlsl_dx9) is refused like the
// techniques above, rather than that target dropped.
Status check_set_layouts(const JsonNode& node, const AxisValues& axes) {
  for (const std::string& name : axes.map_layout) {
    const std::optional<MapLayout> layout = parse_map_layout(name);
    for (Target target : axes.target) {
      const std::string why = layout ? layout_unsupported(*layout, target) : "";
      if (why.empty()) continue;
      if (node.has("target")) {
        return node.member("target").error(why + "; leave " + std::string(to_string(target)) +
                                           " out of this set's 'target' list");
      }
      return node.error(why + "; this set takes the top-level targets: give it a 'target' " +
                        "list without " + std::string(to_string(target)));
    }
  }
  return {};
}

// "technique, ..., target, forms": a set's keys, the axes and its forms.
constexpr std::array<std::string_view, kAxisKeys.size() + 1> kSetKeys = [] {
  std::array<std::string_view, kAxisKeys.size() + 1> keys{};
  std::ranges::copy(kAxisKeys, keys.begin());
  keys.back() = "forms";
  return keys;
}();

// Every technique of the set is built in at least one of its forms: one
// with none of them would leave a variant with nothing to draw.
Status check_set_forms(const JsonNode& node, const VariantSet& set) {
  for (Technique technique : set.axes.technique) {
    if (std::ranges::any_of(set.forms, [&](Form form) { return has_form(technique, form); })) {
      continue;
    }
    const std::string what =
        "technique " + std::string(to_string(technique)) +
        " has none of the forms asked; its forms: " + to_string(technique_forms(technique));
    if (node.has("forms")) return node.member("forms").error(what);
    return node.error(what + " (this set takes the top-level forms; give it a 'forms' list)");
  }
  return {};
}

Result<VariantSet> read_set(const JsonNode& node, const Manifest& manifest) {
  PENUMBRA_TRY(node.expect_keys(kSetKeys));
  VariantSet set{.json_path = node.path(), .axes = {}, .forms = manifest.forms};
  PENUMBRA_TRY(read_axes(node, manifest.disks, set.axes));
  if (node.has("forms")) PENUMBRA_TRY(read_forms(node.member("forms"), set.forms));
  PENUMBRA_TRY(check_set_forms(node, set));
  PENUMBRA_TRY(check_set_keys(node, set.axes));
  PENUMBRA_TRY(check_kernels(node, set.axes));
  if (set.axes.target.empty()) set.axes.target = manifest.targets;
  PENUMBRA_TRY(check_set_targets(node, set.axes));
  PENUMBRA_TRY(check_set_exact(node, set.axes));
  PENUMBRA_TRY(check_set_layouts(node, set.axes));
  return set;
}

Result<Exclusion> read_exclusion(const JsonNode& node, const Manifest& manifest) {
  PENUMBRA_TRY(node.expect_keys(kAxisKeys));
  Exclusion exclusion{.json_path = node.path(), .match = {}};
  PENUMBRA_TRY(read_axes(node, manifest.disks, exclusion.match));
  const AxisValues& match = exclusion.match;
  const bool empty =
      match.technique.empty() && match.target.empty() &&
      std::ranges::none_of(kKeyAxes, [&](Axis axis) { return is_given(match, axis); });
  if (empty) {
    return node.error("an exclusion needs at least one key; allowed keys: " +
                      join(kAxisKeys, ", "));
  }
  return exclusion;
}

}  // namespace

Status read_sets(const JsonNode& root, Manifest& manifest) {
  if (!root.has("sets")) return root.error("missing key 'sets'; a manifest needs at least one set");
  const JsonNode sets = root.member("sets");
  PENUMBRA_TRY(sets.expect_array());
  if (sets.value().empty()) return sets.error("expected at least one set, got an empty list");
  for (std::size_t i = 0; i < sets.value().size(); ++i) {
    Result<VariantSet> set = read_set(sets.element(i), manifest);
    if (!set) return set.error();
    manifest.sets.push_back(std::move(*set));
  }
  return {};
}

Status read_exclusions(const JsonNode& root, Manifest& manifest) {
  if (!root.has("exclude")) return {};
  const JsonNode exclude = root.member("exclude");
  PENUMBRA_TRY(exclude.expect_array());
  for (std::size_t i = 0; i < exclude.value().size(); ++i) {
    Result<Exclusion> exclusion = read_exclusion(exclude.element(i), manifest);
    if (!exclusion) return exclusion.error();
    manifest.exclude.push_back(std::move(*exclusion));
  }
  return {};
}

}  // namespace penumbra::manifest_detail
