#include <array>
#include <string_view>

#include "manifest/json_node.hpp"
#include "manifest/sections.hpp"
#include "penumbra/compiler/manifest.hpp"

namespace penumbra {
namespace {

using manifest_detail::JsonNode;

constexpr std::array<std::string_view, 5> kManifestKeys = {"schema", "disks", "targets", "sets",
                                                           "exclude"};

// nlohmann's what() reads "[json.exception.parse_error.101] parse error at
// line 3, column 5: ..."; users need the part after the tag.
std::string without_exception_tag(std::string_view what) {
  if (const auto end = what.find("] "); end != std::string_view::npos) what.remove_prefix(end + 2);
  return std::string(what);
}

// Sections are read in dependency order: sets name disks and default to targets.
Result<Manifest> read_manifest(const JsonNode& root) {
  PENUMBRA_TRY(root.expect_keys(kManifestKeys));
  PENUMBRA_TRY(manifest_detail::read_schema(root));
  Manifest manifest;
  PENUMBRA_TRY(manifest_detail::read_disks(root, manifest));
  PENUMBRA_TRY(manifest_detail::read_default_targets(root, manifest));
  PENUMBRA_TRY(manifest_detail::read_sets(root, manifest));
  PENUMBRA_TRY(manifest_detail::read_exclusions(root, manifest));
  return manifest;
}

}  // namespace

// The readers check types before every access, so the catch-all below only
// turns a bug into an internal error instead of an exception.
Result<Manifest> parse_manifest(std::string_view json_text, std::string_view source_name) {
  const std::string source(source_name);
  try {
    const nlohmann::json document = nlohmann::json::parse(json_text);
    Result<Manifest> manifest = read_manifest(JsonNode(document, source));
    if (manifest) manifest->source = source;
    return manifest;
  } catch (const nlohmann::json::parse_error& e) {
    return make_error(Error::Kind::bad_input, source,
                      "malformed JSON: " + without_exception_tag(e.what()));
  } catch (const nlohmann::json::exception& e) {
    return make_error(Error::Kind::internal, source, without_exception_tag(e.what()));
  }
}

}  // namespace penumbra
