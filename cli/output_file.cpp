// A long verification must not end in "cannot write the report": the
// destination is checked before it starts, and written only at the end.
#include "output_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace penumbra::cli {

Status check_output_file(const std::string& path, const std::string& argument) {
  namespace fs = std::filesystem;
  const fs::path file(path);
  const fs::path dir = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  const std::string where = argument.empty() ? path : argument + " " + path;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    return make_error(
        Error::Kind::bad_input, where,
        "no directory " + dir.string() + "; allowed: a file in an existing directory");
  }
  if (fs::is_directory(file, ec) || !file.has_filename()) {
    return make_error(Error::Kind::bad_input, where,
                      "is a directory; allowed: a file in an existing directory");
  }
  if (const std::string why = why_unwritable(dir); !why.empty()) {
    return make_error(Error::Kind::bad_input, where,
                      "cannot write into " + dir.string() + ": " + why +
                          "; allowed: a file in a directory penumbra may write to");
  }
  return {};
}

std::string why_unwritable(const std::filesystem::path& dir) {
  // A file is written beside itself and renamed: the directory must take
  // new files (EACCES; EROFS on a read-only mount and EPERM on an immutable
  // directory, even for root).
  if (::access(dir.c_str(), W_OK | X_OK) == 0) return {};
  return std::strerror(errno);
}

}  // namespace penumbra::cli
