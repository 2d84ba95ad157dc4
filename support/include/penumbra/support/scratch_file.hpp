// A file for one call's intermediate output: a name in the system's
// temporary folder that no other call, thread or process takes, and the
// file removed when the object goes.
#pragma once

#include <filesystem>
#include <string_view>

namespace penumbra {

class ScratchFile {
 public:
  // "penumbra-<purpose>-<pid>-<n><extension>"; nothing is created.
  ScratchFile(std::string_view purpose, std::string_view extension);
  ~ScratchFile();
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace penumbra
