// Permutation manifests: which variants to build, for which targets.
// The schema, expansion rules and error format are in docs/manifest.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/model/model.hpp"
#include "penumbra/support/result.hpp"

namespace penumbra {

// The built-in disk family (the NVIDIA PCSS whitepaper's 16 points); never declared.
inline constexpr std::string_view kWhitepaperDisk = "whitepaper16";

// How many variants a manifest may expand to unless its "max_variants" says
// otherwise; the most it may say is kMaxVariants (penumbra/model/model.hpp).
inline constexpr int kDefaultMaxVariants = 10000;

// The longest disk family name: it ends variant names and file names.
inline constexpr std::size_t kMaxDiskNameLength = 32;

// A generated disk family from "disks": one disk per sample count.
struct DiskFamily {
  std::string method = "sample_elimination";  // a generate_disk method
  std::uint64_t seed = 1;
};

// Allowed values per variant axis; an empty list means "not given".
struct AxisValues {
  std::vector<Technique> technique;
  std::vector<int> blocker_samples;
  std::vector<int> pcf_samples;
  std::vector<int> kernel;
  std::vector<std::string> disk;       // family names
  std::vector<std::string> traversal;  // kBruteForceTraversal
  std::vector<int> max_nodes;
  std::vector<int> blur_radius;           // 1..kMaxBlurRadius
  std::vector<bool> depth_aware;          // false gives variants with the key unset
  std::vector<std::string> rotation;      // kIgnRotation
  std::vector<bool> receiver_plane;       // false gives variants with the key unset
  std::vector<std::string> map_encoding;  // "linear" gives variants with the key unset
  std::vector<std::string> map_layout;    // "single" gives variants with the key unset
  std::vector<int> light_bits;            // kAllowedLightBits
  std::vector<Target> target;
};

// One entry of "sets": the cartesian product of its axes. `axes.target`
// holds the manifest's "targets" when the set gives none, and `forms` the
// manifest's "forms" when the set gives none.
struct VariantSet {
  std::string json_path;  // e.g. "/sets/2", for messages
  AxisValues axes;
  std::vector<Form> forms;  // in kAllForms order
};

// One entry of "exclude": matches variants whose keys are among every given
// axis's values, and removes the given targets from them (all when none given).
struct Exclusion {
  std::string json_path;  // e.g. "/exclude/0"
  AxisValues match;
};

// A parsed and validated manifest, not yet expanded.
struct Manifest {
  std::string source;                       // file name used in messages
  std::map<std::string, DiskFamily> disks;  // declared families by name
  std::vector<Target> targets;              // default targets of every set
  int max_variants = kDefaultMaxVariants;   // 1..kMaxVariants
  // The default forms of every set: all of them unless "forms" says otherwise.
  std::vector<Form> forms{kAllForms.begin(), kAllForms.end()};
  std::vector<VariantSet> sets;
  std::vector<Exclusion> exclude;
};

// Reads and validates a manifest file. Errors: io when the file cannot be
// read; bad_input naming the file, the JSON path and what is allowed, and
// where the offending value is: `where` is "FILE:LINE:COL: /json/path".
Result<Manifest> load_manifest(const std::filesystem::path& path);

// The same for manifest text; `source_name` stands for the file in messages.
Result<Manifest> parse_manifest(std::string_view json_text, std::string_view source_name);

// All variants with their disks, exclusions applied and duplicates merged,
// sorted by technique (Technique's order) and then by keys.
Result<std::vector<Variant>> expand(const Manifest& manifest);

// load_manifest() then expand(): the variants of a manifest file.
Result<std::vector<Variant>> load_variants(const std::filesystem::path& path);

}  // namespace penumbra
