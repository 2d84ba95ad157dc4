#include "penumbra/compiler/shaderlib_source.hpp"

#include <system_error>

#include "penumbra/shaderlib/files.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra {
namespace {

class EmbeddedShaderlib final : public ShaderlibSource {
 public:
  std::optional<std::string> read(std::string_view path) const override {
    auto text = shaderlib::file(path);
    if (!text) return std::nullopt;
    return std::string(*text);
  }
  std::string location(std::string_view path) const override {
    return "shaderlib/" + std::string(path);
  }
  bool on_disk() const override { return false; }
};

class DirectoryShaderlib final : public ShaderlibSource {
 public:
  explicit DirectoryShaderlib(std::filesystem::path dir) : dir_(std::move(dir)) {}
  std::optional<std::string> read(std::string_view path) const override {
    const std::filesystem::path file = dir_ / path;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) return std::nullopt;
    auto text = read_file(file);
    if (!text) return std::nullopt;
    return std::move(*text);
  }
  std::string location(std::string_view path) const override {
    return (dir_ / path).lexically_normal().string();
  }
  bool on_disk() const override { return true; }

 private:
  std::filesystem::path dir_;
};

}  // namespace

std::shared_ptr<const ShaderlibSource> embedded_shaderlib() {
  static const auto source = std::make_shared<const EmbeddedShaderlib>();
  return source;
}

Result<std::shared_ptr<const ShaderlibSource>> shaderlib_directory(
    const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    return make_error(Error::Kind::bad_input, dir.string(),
                      "is not a directory (a shader library folder with common/, techniques/ "
                      "and passes/ is allowed)");
  }
  if (!std::filesystem::is_regular_file(dir / "passes" / "query.frag", ec)) {
    return make_error(Error::Kind::bad_input, dir.string(),
                      "has no passes/query.frag: not a shader library folder (one with "
                      "common/, techniques/ and passes/, like the source tree's shaderlib/)");
  }
  return std::shared_ptr<const ShaderlibSource>(std::make_shared<const DirectoryShaderlib>(dir));
}

}  // namespace penumbra
