#include <fstream>
#include <iterator>

#include "penumbra/compiler/manifest.hpp"

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
  std::ifstream in(path, std::ios::binary);
  if (!in) return io_error("the file could not be opened");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) return io_error("reading failed");
  return parse_manifest(text, name);
}

Result<std::vector<Variant>> load_variants(const std::filesystem::path& path) {
  auto manifest = load_manifest(path);
  if (!manifest) return manifest.error();
  return expand(*manifest);
}

}  // namespace penumbra
