#include <array>
#include <string_view>

#include "manifest/json_locate.hpp"
#include "manifest/json_node.hpp"
#include "manifest/sections.hpp"
#include "penumbra/compiler/manifest.hpp"

namespace penumbra {
namespace {

using manifest_detail::JsonNode;

constexpr std::array<std::string_view, 7> kManifestKeys = {
    "schema", "disks", "targets", "forms", "sets", "exclude", "max_variants"};

// Sections are read in dependency order: sets name disks and default to
// targets and forms.
Result<Manifest> read_manifest(const JsonNode& root) {
  PENUMBRA_TRY(root.expect_keys(kManifestKeys));
  PENUMBRA_TRY(manifest_detail::read_schema(root));
  Manifest manifest;
  PENUMBRA_TRY(manifest_detail::read_disks(root, manifest));
  PENUMBRA_TRY(manifest_detail::read_default_targets(root, manifest));
  PENUMBRA_TRY(manifest_detail::read_default_forms(root, manifest));
  PENUMBRA_TRY(manifest_detail::read_max_variants(root, manifest));
  PENUMBRA_TRY(manifest_detail::read_sets(root, manifest));
  PENUMBRA_TRY(manifest_detail::read_exclusions(root, manifest));
  return manifest;
}

}  // namespace

// The readers check types before every access, so the catch-all below only
// turns a bug into an internal error instead of an exception.
Result<Manifest> parse_manifest(std::string_view json_text, std::string_view source_name) {
  const std::string source(source_name);
  // nlohmann stops at a NUL byte as at the end of the text, so whatever
  // follows one would be ignored. Worded as its syntax errors, so the place
  // is found the same way.
  if (const auto nul = json_text.find('\0'); nul != std::string_view::npos) {
    const manifest_detail::TextPosition at = manifest_detail::position_of(json_text, nul);
    return make_error(Error::Kind::bad_input, source,
                      "malformed JSON: parse error at line " + std::to_string(at.line) +
                          ", column " + std::to_string(at.column) +
                          ": a NUL byte; JSON text may not contain NUL bytes");
  }
  try {
    const nlohmann::json document = nlohmann::json::parse(json_text);
    Result<Manifest> manifest = read_manifest(JsonNode(document, source));
    if (manifest) manifest->source = source;
    return manifest;
  } catch (const nlohmann::json::parse_error& e) {
    return make_error(Error::Kind::bad_input, source, "malformed JSON: " + json_exception_text(e));
  } catch (const nlohmann::json::exception& e) {
    return make_error(Error::Kind::internal, source, json_exception_text(e));
  }
}

}  // namespace penumbra
