#include <array>
#include <string_view>

#include "manifest/axes.hpp"
#include "manifest/sections.hpp"
#include "penumbra/compiler/disk.hpp"
#include "penumbra/support/text.hpp"

namespace penumbra::manifest_detail {
namespace {

constexpr int kSchemaVersion = 1;
constexpr std::array<std::string_view, 2> kDiskKeys = {"method", "seed"};

// Family names end variant names and file names, so keep them to [a-z][a-z0-9_]*.
bool is_family_name(std::string_view name) {
  if (name.empty() || name.front() < 'a' || name.front() > 'z') return false;
  for (char c : name) {
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
  }
  return true;
}

Result<DiskFamily> read_disk_family(const JsonNode& node) {
  PENUMBRA_TRY(node.expect_keys(kDiskKeys));
  DiskFamily family;
  if (node.has("method")) {
    const JsonNode method_node = node.member("method");
    Result<std::string> method = method_node.string();
    if (!method) return method.error();
    if (Status status = check_disk_method(*method); !status)
      return method_node.error(status.error());
    family.method = *method;
  }
  if (node.has("seed")) {
    Result<std::uint64_t> seed = node.member("seed").unsigned_integer();
    if (!seed) return seed.error();
    family.seed = *seed;
  }
  return family;
}

}  // namespace

Status read_schema(const JsonNode& root) {
  if (!root.has("schema")) {
    return root.error("missing key 'schema'; allowed value " + std::to_string(kSchemaVersion));
  }
  const JsonNode node = root.member("schema");
  Result<int> version = node.integer();
  if (!version) return version.error();
  if (*version == kSchemaVersion) return {};
  return node.error("schema " + std::to_string(*version) + " is not supported; allowed value " +
                    std::to_string(kSchemaVersion));
}

Status read_disks(const JsonNode& root, Manifest& manifest) {
  if (!root.has("disks")) return {};
  const JsonNode disks = root.member("disks");
  PENUMBRA_TRY(disks.expect_object());
  for (const auto& [name, unused] : disks.value().items()) {
    const JsonNode node = disks.member(name);
    if (name == kWhitepaperDisk) {
      return node.error("'" + name + "' is built in; give generated disks another name");
    }
    if (name.size() > kMaxDiskNameLength) {
      // The name ends variant and file names; a long one would fail only
      // when the files are written, after every shader was compiled.
      return node.error("disk name '" + shorten(name, 40) + "' is " + std::to_string(name.size()) +
                        " characters long; allowed at most " + std::to_string(kMaxDiskNameLength) +
                        " characters");
    }
    if (!is_family_name(name)) {
      return node.error("disk name '" + shorten(name) +
                        "' is not allowed; use lowercase letters, digits and '_', starting with "
                        "a letter");
    }
    Result<DiskFamily> family = read_disk_family(node);
    if (!family) return family.error();
    manifest.disks.emplace(name, *family);
  }
  return {};
}

Status read_default_targets(const JsonNode& root, Manifest& manifest) {
  if (!root.has("targets")) {
    manifest.targets.assign(kAllTargets.begin(), kAllTargets.end());
    return {};
  }
  return read_targets(root.member("targets"), manifest.targets);
}

Status read_default_forms(const JsonNode& root, Manifest& manifest) {
  if (!root.has("forms")) return {};
  return read_forms(root.member("forms"), manifest.forms);
}

Status read_max_variants(const JsonNode& root, Manifest& manifest) {
  if (!root.has("max_variants")) return {};
  const JsonNode node = root.member("max_variants");
  Result<int> most = node.integer();
  if (!most) return most.error();
  if (*most < 1 || *most > kMaxVariants) {
    return node.error("max_variants " + std::to_string(*most) + " is out of range; allowed 1.." +
                      std::to_string(kMaxVariants));
  }
  manifest.max_variants = *most;
  return {};
}

}  // namespace penumbra::manifest_detail
