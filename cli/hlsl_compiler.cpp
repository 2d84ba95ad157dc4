#include "hlsl_compiler.hpp"

#include <unistd.h>

#include <cstdlib>
#include <vector>

namespace penumbra::cli {
namespace {

// `path` when it is an executable file; else an error naming `given_by`.
Result<std::filesystem::path> executable(const std::filesystem::path& path,
                                         const std::string& given_by) {
  if (std::filesystem::is_regular_file(path) && ::access(path.c_str(), X_OK) == 0) return path;
  return make_error(Error::Kind::bad_input, given_by,
                    path.string() + " is not an executable file (vkd3d-compiler 2.1 or newer)");
}

}  // namespace

Result<std::filesystem::path> find_hlsl_compiler(const std::string& flag) {
  if (!flag.empty()) return executable(flag, "--hlsl-compiler");
  const char* env = std::getenv("PENUMBRA_HLSL_COMPILER");
  if (env && *env) return executable(env, "PENUMBRA_HLSL_COMPILER");
  std::vector<std::filesystem::path> caches;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) caches.emplace_back(xdg);
  if (const char* home = std::getenv("HOME"); home && *home) {
    caches.push_back(std::filesystem::path(home) / ".cache");
  }
  for (const std::filesystem::path& cache : caches) {
    const std::filesystem::path installed = cache / "penumbra/vkd3d/bin/vkd3d-compiler";
    if (::access(installed.c_str(), X_OK) == 0) return installed;
  }
  return std::filesystem::path();
}

}  // namespace penumbra::cli
