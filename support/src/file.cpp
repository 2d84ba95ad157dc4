// One reader for every whole-file read, so each caller gets the same io
// errors; callers that need a friendlier message wrap this one.
#include "penumbra/support/file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace penumbra {
namespace {

// The system's reason (strerror) leads, so "No such file or directory" and
// "Permission denied" reach the user as the system names them.
Error io_error(const std::filesystem::path& path, const char* doing, int error) {
  return make_error(Error::Kind::io, path.string(),
                    std::string(doing) + ": " + std::strerror(error));
}

}  // namespace

Result<std::string> read_file(const std::filesystem::path& path) {
  if (path.empty()) {
    return make_error(Error::Kind::io, "", "cannot read a file with an empty name");
  }
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return io_error(path, "cannot read", EISDIR);
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             &std::fclose);
  if (!file) return io_error(path, "cannot open the file", errno);
  std::string bytes;
  char buffer[1 << 16];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, file.get())) {
    bytes.append(buffer, n);
  }
  if (std::ferror(file.get())) return io_error(path, "cannot read the file", errno);
  return bytes;
}

Status write_file(const std::filesystem::path& path, std::string_view bytes) {
  if (path.empty()) {
    return make_error(Error::Kind::io, "", "cannot write a file with an empty name");
  }
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return io_error(path, "cannot create the file", errno);
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int error = errno;
      ::close(fd);
      ::unlink(path.c_str());
      return io_error(path, ("cannot write " + std::to_string(bytes.size()) + " bytes").c_str(),
                      error);
    }
    written += std::size_t(n);
  }
  // close() reports what a delayed write (NFS, a full disk) could not do.
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(path.c_str());
    return io_error(path, "cannot write the file", error);
  }
  return {};
}

}  // namespace penumbra
