#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

#include "manifest/axes.hpp"
#include "penumbra/compiler/disk.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/model/map_layout.hpp"
#include "penumbra/model/shader_contract.hpp"

namespace penumbra {
namespace {

using manifest_detail::Axis;
using manifest_detail::uses;

// Replaces each VariantKeys of `out` by one copy per value of the axis, when
// the technique uses the axis and the set gives it (an optional key left
// out stays unset).
template <typename T>
void multiply(std::vector<VariantKeys>& out, Technique technique, Axis axis,
              const std::vector<T>& values, std::optional<T> VariantKeys::*member) {
  if (!uses(technique, axis) || values.empty()) return;
  std::vector<VariantKeys> product;
  product.reserve(out.size() * values.size());
  for (const VariantKeys& keys : out) {
    for (const T& value : values) {
      product.push_back(keys);
      product.back().*member = value;
    }
  }
  out = std::move(product);
}

// The set's cartesian product for one technique, kernel varying slowest.
// The flags' false is their default, so the key stays unset.
std::vector<VariantKeys> key_product(Technique technique, const AxisValues& axes) {
  std::vector<VariantKeys> out(1);
  multiply(out, technique, Axis::kernel, axes.kernel, &VariantKeys::kernel);
  multiply(out, technique, Axis::blocker_samples, axes.blocker_samples,
           &VariantKeys::blocker_samples);
  multiply(out, technique, Axis::pcf_samples, axes.pcf_samples, &VariantKeys::pcf_samples);
  multiply(out, technique, Axis::disk, axes.disk, &VariantKeys::disk);
  multiply(out, technique, Axis::traversal, axes.traversal, &VariantKeys::traversal);
  multiply(out, technique, Axis::max_nodes, axes.max_nodes, &VariantKeys::max_nodes);
  multiply(out, technique, Axis::blur_radius, axes.blur_radius, &VariantKeys::blur_radius);
  multiply(out, technique, Axis::depth_aware, axes.depth_aware, &VariantKeys::depth_aware);
  multiply(out, technique, Axis::light_bits, axes.light_bits, &VariantKeys::light_bits);
  multiply(out, technique, Axis::rotation, axes.rotation, &VariantKeys::rotation);
  multiply(out, technique, Axis::receiver_plane, axes.receiver_plane, &VariantKeys::receiver_plane);
  multiply(out, technique, Axis::map_encoding, axes.map_encoding, &VariantKeys::map_encoding);
  multiply(out, technique, Axis::map_layout, axes.map_layout, &VariantKeys::map_layout);
  for (VariantKeys& keys : out) {
    if (!keys.depth_aware.value_or(true)) keys.depth_aware.reset();
    if (!keys.receiver_plane.value_or(true)) keys.receiver_plane.reset();
    if (keys.map_encoding == to_string(MapEncoding::linear)) keys.map_encoding.reset();
    if (keys.map_layout == to_string(MapLayout::single)) keys.map_layout.reset();
  }
  return out;
}

constexpr std::uint64_t kSaturated = std::numeric_limits<std::uint64_t>::max();

std::uint64_t saturating_multiply(std::uint64_t a, std::uint64_t b) {
  return b != 0 && a > kSaturated / b ? kSaturated : a * b;
}

// How many keys key_product() gives: counted before anything is made, so a
// set of millions is refused in microseconds.
std::uint64_t product_size(Technique technique, const AxisValues& axes) {
  std::uint64_t size = 1;
  for (Axis axis : manifest_detail::kKeyAxes) {
    if (!uses(technique, axis)) continue;
    std::size_t count = 0;
    switch (axis) {
      case Axis::kernel:
        count = axes.kernel.size();
        break;
      case Axis::blocker_samples:
        count = axes.blocker_samples.size();
        break;
      case Axis::pcf_samples:
        count = axes.pcf_samples.size();
        break;
      case Axis::disk:
        count = axes.disk.size();
        break;
      case Axis::traversal:
        count = axes.traversal.size();
        break;
      case Axis::max_nodes:
        count = axes.max_nodes.size();
        break;
      case Axis::blur_radius:
        count = axes.blur_radius.size();
        break;
      case Axis::depth_aware:
        count = axes.depth_aware.size();
        break;
      case Axis::light_bits:
        count = axes.light_bits.size();
        break;
      case Axis::rotation:
        count = axes.rotation.size();
        break;
      case Axis::receiver_plane:
        count = axes.receiver_plane.size();
        break;
      case Axis::map_encoding:
        count = axes.map_encoding.size();
        break;
      case Axis::map_layout:
        count = axes.map_layout.size();
        break;
    }
    size = saturating_multiply(size, std::max<std::size_t>(count, 1));
  }
  return size;
}

Error too_many_variants(const Manifest& manifest, const VariantSet& set, std::string what) {
  return make_error(Error::Kind::bad_input, manifest.source + ": " + set.json_path,
                    std::move(what) + "; allowed at most " + std::to_string(manifest.max_variants) +
                        " (set the top-level max_variants to allow more, up to " +
                        std::to_string(kMaxVariants) + ")");
}

// whitepaper16 serves any count up to its 16 points as a prefix; other
// families are generated. `key` names the sample axis in messages.
Result<Disk> resolve_disk(const Manifest& manifest, const std::string& family, int count,
                          std::string_view key) {
  if (family == kWhitepaperDisk) {
    Disk disk = whitepaper16();
    const int size = static_cast<int>(disk.points.size());
    if (count < 1 || count > size) {
      return make_error(Error::Kind::bad_input, "",
                        std::string(key) + " " + std::to_string(count) + " is out of range for " +
                            disk.name + "; allowed 1.." + std::to_string(size) + " (declare a " +
                            "generated disk under /disks for more samples)");
    }
    disk.points.resize(static_cast<std::size_t>(count));
    disk.normalized_min_distance = normalized_min_distance(disk.points);
    return disk;
  }
  const auto found = manifest.disks.find(family);
  if (found == manifest.disks.end()) {
    return make_error(Error::Kind::bad_input, "", "disk '" + family + "' is not declared");
  }
  Result<Disk> disk = generate_disk({count, found->second.seed, found->second.method});
  if (disk) disk->name = family;
  return disk;
}

// Disks already made in this expansion, by (family, count): every variant
// with the same disk and sample count gets the same points, generated once.
using DiskCache = std::map<std::pair<std::string, int>, Disk>;

// Only successes are kept: an error stops the expansion, and its message
// names the sample axis that asked.
Result<Disk> cached_disk(DiskCache& cache, const Manifest& manifest, const std::string& family,
                         int count, std::string_view key) {
  const auto found = cache.find({family, count});
  if (found != cache.end()) return found->second;
  Result<Disk> disk = resolve_disk(manifest, family, count, key);
  if (disk) cache.emplace(std::pair{family, count}, *disk);
  return disk;
}

Result<Variant> make_variant(DiskCache& cache, const Manifest& manifest, Technique technique,
                             const VariantKeys& keys) {
  Variant variant;
  variant.name = variant_name(technique, keys);
  variant.technique = technique;
  variant.keys = keys;
  variant.forms.clear();  // the union of the sets' forms, added by expand()
  if (keys.blocker_samples && keys.disk) {
    Result<Disk> disk =
        cached_disk(cache, manifest, *keys.disk, *keys.blocker_samples, "blocker_samples");
    if (!disk) return disk.error();
    variant.blocker_disk = std::move(*disk);
  }
  if (keys.pcf_samples && keys.disk) {
    Result<Disk> disk = cached_disk(cache, manifest, *keys.disk, *keys.pcf_samples, "pcf_samples");
    if (!disk) return disk.error();
    variant.pcf_disk = std::move(*disk);
  }
  if (keys.blur_radius) variant.blur_weights = gaussian_weights(*keys.blur_radius);
  return variant;
}

template <typename T>
bool contains(const std::vector<T>& values, const T& value) {
  return std::find(values.begin(), values.end(), value) != values.end();
}

// An axis an exclusion does not give matches anything; one it gives matches
// only variants that have the key with one of its values.
template <typename T>
bool allows(const std::vector<T>& values, const std::optional<T>& value) {
  return values.empty() || (value && contains(values, *value));
}

// A flag (depth_aware, receiver_plane) is unset for false, so a technique
// that takes the key matches `false` without it; the others never have it.
bool allows_flag(const std::vector<bool>& values, const Variant& variant, Axis axis,
                 const std::optional<bool>& flag) {
  if (values.empty()) return true;
  if (!uses(variant.technique, axis)) return false;
  return contains(values, flag.value_or(false));
}

// A key left unset for its default (map_encoding's linear, map_layout's
// single), whose value `name` a technique that takes the key matches
// without it; the others never have it.
bool allows_defaulted(const std::vector<std::string>& values, const Variant& variant, Axis axis,
                      std::string_view name) {
  if (values.empty()) return true;
  if (!uses(variant.technique, axis)) return false;
  return contains(values, std::string(name));
}

bool matches(const AxisValues& match, const Variant& variant) {
  return (match.technique.empty() || contains(match.technique, variant.technique)) &&
         allows(match.kernel, variant.keys.kernel) &&
         allows(match.blocker_samples, variant.keys.blocker_samples) &&
         allows(match.pcf_samples, variant.keys.pcf_samples) &&
         allows(match.disk, variant.keys.disk) && allows(match.traversal, variant.keys.traversal) &&
         allows(match.max_nodes, variant.keys.max_nodes) &&
         allows(match.blur_radius, variant.keys.blur_radius) &&
         allows_flag(match.depth_aware, variant, Axis::depth_aware, variant.keys.depth_aware) &&
         allows(match.light_bits, variant.keys.light_bits) &&
         allows(match.rotation, variant.keys.rotation) &&
         allows_flag(match.receiver_plane, variant, Axis::receiver_plane,
                     variant.keys.receiver_plane) &&
         allows_defaulted(match.map_encoding, variant, Axis::map_encoding,
                          to_string(map_encoding(variant.keys))) &&
         allows_defaulted(match.map_layout, variant, Axis::map_layout,
                          to_string(map_layout(variant.keys)));
}

void apply(const Exclusion& exclusion, Variant& variant) {
  if (!matches(exclusion.match, variant)) return;
  if (exclusion.match.target.empty()) {
    variant.targets.clear();
  } else {
    std::erase_if(variant.targets,
                  [&](Target target) { return contains(exclusion.match.target, target); });
  }
}

}  // namespace

// Variants are keyed by name, so a variant that several sets produce is built
// once and gets the union of their targets and of their forms.
Result<std::vector<Variant>> expand(const Manifest& manifest) {
  std::map<std::string, Variant> by_name;
  DiskCache disks;
  const auto max = static_cast<std::uint64_t>(manifest.max_variants);
  for (const VariantSet& set : manifest.sets) {
    std::uint64_t set_size = 0;
    for (Technique technique : set.axes.technique) {
      const std::uint64_t size = product_size(technique, set.axes);
      set_size = size > kSaturated - set_size ? kSaturated : set_size + size;
    }
    if (set_size > max) {
      return too_many_variants(manifest, set,
                               "this set expands to " + std::to_string(set_size) + " variants");
    }
    for (Technique technique : set.axes.technique) {
      for (const VariantKeys& keys : key_product(technique, set.axes)) {
        const std::string name = variant_name(technique, keys);
        auto it = by_name.find(name);
        if (it == by_name.end()) {
          Result<Variant> variant = make_variant(disks, manifest, technique, keys);
          if (!variant) {
            return make_error(variant.error().kind, manifest.source + ": " + set.json_path,
                              "variant " + name + ": " + variant.error().message);
          }
          it = by_name.emplace(name, std::move(*variant)).first;
          if (by_name.size() > max) {
            return too_many_variants(
                manifest, set,
                "the sets up to this one expand to more than " + std::to_string(max) + " variants");
          }
        }
        std::vector<Target>& targets = it->second.targets;
        targets.insert(targets.end(), set.axes.target.begin(), set.axes.target.end());
        std::vector<Form>& forms = it->second.forms;
        forms.insert(forms.end(), set.forms.begin(), set.forms.end());
      }
    }
  }

  std::vector<Variant> variants;
  for (auto& [name, variant] : by_name) {
    std::ranges::sort(variant.targets);
    variant.targets.erase(std::unique(variant.targets.begin(), variant.targets.end()),
                          variant.targets.end());
    variant.forms = built_forms(variant);  // those its technique has, in kAllForms order
    for (const Exclusion& exclusion : manifest.exclude) apply(exclusion, variant);
    if (!variant.targets.empty()) variants.push_back(std::move(variant));
  }
  if (variants.empty() && !manifest.exclude.empty()) {
    // Else `list` prints nothing and `build` writes an empty library, silently.
    return make_error(Error::Kind::bad_input, manifest.source + ": /exclude",
                      "the exclusions remove every variant the sets give; allowed: exclusions "
                      "that leave at least one variant and target");
  }
  std::ranges::sort(variants, variant_less);
  return variants;
}

}  // namespace penumbra
