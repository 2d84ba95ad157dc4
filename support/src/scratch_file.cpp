#include "penumbra/support/scratch_file.hpp"

#include <unistd.h>

#include <atomic>
#include <string>

namespace penumbra {

ScratchFile::ScratchFile(std::string_view purpose, std::string_view extension) {
  static std::atomic<unsigned> counter{0};
  path_ = std::filesystem::temp_directory_path() /
          ("penumbra-" + std::string(purpose) + "-" + std::to_string(::getpid()) + "-" +
           std::to_string(counter++) + std::string(extension));
}

ScratchFile::~ScratchFile() {
  std::error_code ignored;
  std::filesystem::remove(path_, ignored);
}

}  // namespace penumbra
