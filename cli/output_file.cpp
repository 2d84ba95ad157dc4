// A long verification must not end in "cannot write the report": the
// destination is checked before it starts, and written only at the end.
#include "output_file.hpp"

#include <filesystem>

namespace penumbra::cli {

Status check_output_file(const std::string& path, const std::string& argument) {
  namespace fs = std::filesystem;
  const fs::path file(path);
  const fs::path dir = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    return make_error(
        Error::Kind::bad_input, argument + " " + path,
        "no directory " + dir.string() + "; allowed: a file in an existing directory");
  }
  if (fs::is_directory(file, ec) || !file.has_filename()) {
    return make_error(Error::Kind::bad_input, argument + " " + path,
                      "is a directory; allowed: a file in an existing directory");
  }
  return {};
}

}  // namespace penumbra::cli
