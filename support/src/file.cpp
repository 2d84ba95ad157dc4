// One reader for every whole-file read, so each caller gets the same io
// errors; callers that need a friendlier message wrap this one.
#include "penumbra/support/file.hpp"

#include <fstream>
#include <iterator>

namespace penumbra {

Result<std::string> read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return make_error(Error::Kind::io, path.string(), "cannot open file for reading");
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) return make_error(Error::Kind::io, path.string(), "cannot read file");
  return bytes;
}

}  // namespace penumbra
