#include "manifest/json_locate.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra {
namespace {

// The path is named as the caller gave it, so messages match the command line.
Result<std::string> read_manifest_text(const std::filesystem::path& path) {
  const std::string name = path.string();
  const auto io_error = [&name](std::string message) {
    return make_error(Error::Kind::io, name, "cannot read the manifest: " + std::move(message));
  };
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return io_error("no such file");
  if (std::filesystem::is_directory(path, ec)) return io_error("it is a directory");
  Result<std::string> text = read_file(path);
  if (!text) return io_error(text.error().message);
  return text;
}

// `error` about the file `path` holding `text`, pointing at its line and column.
Error located(Error error, std::string_view text, const std::filesystem::path& path) {
  manifest_detail::add_position(error, text, path.string());
  return error;
}

}  // namespace

Result<Manifest> load_manifest(const std::filesystem::path& path) {
  auto text = read_manifest_text(path);
  if (!text) return text.error();
  auto manifest = parse_manifest(*text, path.string());
  if (!manifest) return located(manifest.error(), *text, path);
  return manifest;
}

Result<std::vector<Variant>> load_variants(const std::filesystem::path& path) {
  auto text = read_manifest_text(path);
  if (!text) return text.error();
  auto manifest = parse_manifest(*text, path.string());
  if (!manifest) return located(manifest.error(), *text, path);
  auto variants = expand(*manifest);
  if (!variants) return located(variants.error(), *text, path);
  return variants;
}

}  // namespace penumbra
