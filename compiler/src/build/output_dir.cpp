#include "build/output_dir.hpp"

namespace penumbra {

Status check_replaceable(const std::filesystem::path& out) {
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(out, ec);
  if (ec || !std::filesystem::exists(status)) return {};
  if (!std::filesystem::is_directory(status)) {
    return make_error(Error::Kind::bad_input, out.string(),
                      "exists and is not a directory; refusing to replace it with a library");
  }
  const bool empty = std::filesystem::is_empty(out, ec);
  if (!ec && !empty && !std::filesystem::exists(out / "index.json", ec)) {
    return make_error(Error::Kind::bad_input, out.string(),
                      "is a non-empty directory without index.json (not a penumbra library); "
                      "refusing to replace it");
  }
  return {};
}

}  // namespace penumbra
