#include "build_cache.hpp"

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "penumbra/compiler/build.hpp"
#include "penumbra/support/atomic_file.hpp"
#include "penumbra/support/content_hash.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::cli {
namespace {

namespace fs = std::filesystem;

// A file's identity for the key without reading it: the HLSL compiler is
// large, and a reinstall changes its size or time.
std::string file_identity(const fs::path& path) {
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  const auto time = fs::last_write_time(path, ec);
  return path.string() + " " + std::to_string(size) + " " +
         std::to_string(time.time_since_epoch().count());
}

// OUT/index.json's size and time: a build writes it last, so another write
// into OUT by anyone changes them or leaves them in place of a library.
std::string index_identity(const fs::path& index) {
  std::error_code ec;
  if (!fs::is_regular_file(index, ec)) return {};
  return file_identity(index);
}

}  // namespace

fs::path cache_directory(const std::string& flag, bool disabled) {
  if (disabled) return {};
  if (!flag.empty()) return fs::absolute(flag);
  if (const char* dir = std::getenv("PENUMBRA_CACHE_DIR"); dir && *dir) return fs::absolute(dir);
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
    return fs::path(xdg) / "penumbra";
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return fs::path(home) / ".cache/penumbra";
  }
  return {};
}

BuildStamp BuildStamp::of(const fs::path& cache_dir, const BuildInputs& inputs) {
  const fs::path out = fs::absolute(inputs.out).lexically_normal();
  ContentHash key;
  key.add(toolchain_id()).add(out.string()).add(inputs.shaderlib);
  key.add(inputs.hlsl_compiler.empty() ? std::string() : file_identity(inputs.hlsl_compiler));
  // Per variant, not the manifest's bytes: an edit to one set leaves the
  // other groups of a split build (--group) current.
  for (const Variant& variant : inputs.variants) {
    key.add(variant_identity(variant));
    for (Target target : variant.targets) key.add(to_string(target));
    for (Form form : variant.forms) key.add(to_string(form));  // --form changes what is written
  }
  BuildStamp stamp;
  stamp.stamp_path_ = cache_dir / "builds" / (content_hash(out.string()) + ".json");
  stamp.index_ = out / "index.json";
  stamp.key_ = key.hex();
  return stamp;
}

std::optional<std::vector<std::string>> BuildStamp::current() const {
  const Result<std::string> text = read_file(stamp_path_);
  if (!text) return std::nullopt;
  const nlohmann::json stamp = nlohmann::json::parse(*text, nullptr, false);
  if (!stamp.is_object() || stamp.value("key", "") != key_ ||
      stamp.value("index", "") != index_identity(index_) || !stamp.contains("files")) {
    return std::nullopt;
  }
  std::vector<std::string> files;
  for (const auto& [path, hash] : stamp["files"].items()) {
    const Result<std::string> bytes = read_file(path);
    if (!bytes || !hash.is_string() || content_hash(*bytes) != hash.get<std::string>()) {
      return std::nullopt;
    }
    files.push_back(path);
  }
  return files;
}

void BuildStamp::record(const std::vector<std::string>& files) const {
  nlohmann::json hashes = nlohmann::json::object();
  for (const std::string& path : files) {
    const Result<std::string> bytes = read_file(path);
    if (!bytes) return;
    hashes[path] = content_hash(*bytes);
  }
  const nlohmann::json stamp = {
      {"key", key_}, {"index", index_identity(index_)}, {"files", hashes}};
  std::error_code ec;
  fs::create_directories(stamp_path_.parent_path(), ec);
  if (!ec) (void)write_file_atomic(stamp_path_, stamp.dump());
}

}  // namespace penumbra::cli
