// Readers for the manifest's top-level sections, in the order they depend on
// each other: disks and targets first, then sets and exclusions.
#pragma once

#include "manifest/json_node.hpp"
#include "penumbra/compiler/manifest.hpp"

namespace penumbra::manifest_detail {

Status read_schema(const JsonNode& root);
Status read_disks(const JsonNode& root, Manifest& manifest);
Status read_default_targets(const JsonNode& root, Manifest& manifest);
// "forms": the forms every set is built in unless it gives its own; all
// three when left out.
Status read_default_forms(const JsonNode& root, Manifest& manifest);
// "max_variants": 1..kMaxVariants, kDefaultMaxVariants when left out.
Status read_max_variants(const JsonNode& root, Manifest& manifest);
Status read_sets(const JsonNode& root, Manifest& manifest);
Status read_exclusions(const JsonNode& root, Manifest& manifest);

}  // namespace penumbra::manifest_detail
