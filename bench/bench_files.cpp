#include "bench_files.hpp"

#include <unistd.h>

#include <string>
#include <system_error>
#include <vector>

namespace penumbra::bench {
namespace {

namespace fs = std::filesystem;

fs::path executable_dir() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self.parent_path();
}

// The first of `candidates` that exists, or an error listing them all.
Result<fs::path> first_existing(const std::vector<fs::path>& candidates, std::string_view what,
                                bool executable) {
  std::string tried;
  for (const fs::path& path : candidates) {
    std::error_code ec;
    const bool found =
        executable ? ::access(path.c_str(), X_OK) == 0 : fs::is_regular_file(path, ec);
    if (found) return path;
    tried += (tried.empty() ? "" : ", ") + path.string();
  }
  return make_error(Error::Kind::io, std::string(what), "not found; looked at " + tried);
}

}  // namespace

Result<fs::path> default_manifest(std::string_view name) {
  const fs::path exe = executable_dir();
  return first_existing({exe / ".." / "share" / "penumbra" / "permutations" / name,
                         fs::current_path() / "permutations" / name},
                        name, false);
}

Result<fs::path> penumbra_executable() {
  const fs::path exe = executable_dir();
  return first_existing({exe / "penumbra", exe / ".." / "penumbra"}, "penumbra", true);
}

}  // namespace penumbra::bench
