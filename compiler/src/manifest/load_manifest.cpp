#include "penumbra/compiler/manifest.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra {

// The path is named as the caller gave it, so messages match the command line.
Result<Manifest> load_manifest(const std::filesystem::path& path) {
  const std::string name = path.string();
  const auto io_error = [&name](std::string message) {
    return make_error(Error::Kind::io, name, "cannot read the manifest: " + std::move(message));
  };
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return io_error("no such file");
  if (std::filesystem::is_directory(path, ec)) return io_error("it is a directory");
  Result<std::string> text = read_file(path);
  if (!text) return io_error(text.error().message);
  return parse_manifest(*text, name);
}

Result<std::vector<Variant>> load_variants(const std::filesystem::path& path) {
  auto manifest = load_manifest(path);
  if (!manifest) return manifest.error();
  return expand(*manifest);
}

}  // namespace penumbra
