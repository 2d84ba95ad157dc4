// Atomic writes and staged directories. Both rely on rename() within one
// directory being atomic, so temporaries always live beside their target.
#include "penumbra/support/atomic_file.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <random>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "penumbra/support/file.hpp"

namespace penumbra {
namespace fs = std::filesystem;

namespace {

// 16 hex digits: enough that concurrent writers never pick the same name.
std::string random_suffix() {
  static thread_local std::mt19937_64 engine{std::random_device{}()};
  static constexpr char kHex[] = "0123456789abcdef";
  std::uint64_t bits = engine();
  std::string suffix(16, '0');
  for (char& c : suffix) {
    c = kHex[bits & 0xf];
    bits >>= 4;
  }
  return suffix;
}

// `final_dir` without a trailing separator, so filename() is its name.
fs::path without_trailing_separator(const fs::path& path) {
  return path.has_filename() ? path : path.parent_path();
}

// `.<name>.<tag>-<random>` beside `path`. Appended into one string: GCC 12's
// -Wrestrict misreads `"." + std::string` (an insert at the front) at -O3.
fs::path sibling(const fs::path& path, std::string_view tag) {
  const std::string name = path.filename().string();
  const std::string suffix = random_suffix();
  std::string leaf;
  leaf.reserve(name.size() + tag.size() + suffix.size() + 3);
  leaf.append(".").append(name).append(".").append(tag).append("-").append(suffix);
  return path.parent_path() / leaf;
}

Error io_error(const fs::path& path, std::string message) {
  return make_error(Error::Kind::io, path.string(), std::move(message));
}

}  // namespace

Status write_file_atomic(const fs::path& path, std::string_view bytes) {
  const fs::path temp = sibling(path, "tmp");
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) return io_error(path, "cannot create temporary file " + temp.string());
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      std::error_code ignored;
      fs::remove(temp, ignored);
      return io_error(path, "cannot write " + std::to_string(bytes.size()) + " bytes");
    }
  }
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    return io_error(path, "cannot replace file: " + ec.message());
  }
  return {};
}

Result<StagedDirectory> StagedDirectory::create(const fs::path& final_dir) {
  const fs::path target = without_trailing_separator(final_dir);
  std::error_code ec;
  if (!target.parent_path().empty()) {
    fs::create_directories(target.parent_path(), ec);
    if (ec) return io_error(target, "cannot create parent directory: " + ec.message());
  }
  const fs::path staging = sibling(target, "staging");
  if (!fs::create_directory(staging, ec) || ec) {
    return io_error(target, "cannot create staging directory " + staging.string() +
                                (ec ? ": " + ec.message() : ": it already exists"));
  }
  return StagedDirectory(target, staging);
}

StagedDirectory::StagedDirectory(fs::path final_dir, fs::path staging)
    : final_(std::move(final_dir)), staging_(std::move(staging)) {}

StagedDirectory::StagedDirectory(StagedDirectory&& other) noexcept
    : final_(std::move(other.final_)),
      staging_(std::move(other.staging_)),
      committed_(std::exchange(other.committed_, true)) {}

StagedDirectory::~StagedDirectory() {
  if (committed_ || staging_.empty()) return;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

namespace {

// The regular files under `root`, relative, sorted.
std::vector<fs::path> tree_files(const fs::path& root, std::error_code& ec) {
  std::vector<fs::path> files;
  for (auto it = fs::recursive_directory_iterator(root, ec); !ec && it != fs::end(it);
       it.increment(ec)) {
    if (it->is_regular_file()) files.push_back(it->path().lexically_relative(root));
  }
  std::ranges::sort(files);
  return files;
}

bool same_bytes(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (fs::file_size(a, ec) != fs::file_size(b, ec) || ec) return false;
  const Result<std::string> left = read_file(a);
  const Result<std::string> right = read_file(b);
  return left && right && *left == *right;
}

// Whether two directories hold the same files with the same bytes.
bool same_tree(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (!fs::is_directory(b, ec)) return false;
  const std::vector<fs::path> left = tree_files(a, ec);
  const std::vector<fs::path> right = tree_files(b, ec);
  if (ec || left != right) return false;
  return std::ranges::all_of(left, [&](const fs::path& f) { return same_bytes(a / f, b / f); });
}

}  // namespace

Result<bool> StagedDirectory::commit_if_changed() {
  if (committed_) return make_error(Error::Kind::internal, final_.string(), "already committed");
  if (!same_tree(staging_, final_)) {
    PENUMBRA_TRY(commit());
    return true;
  }
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
  committed_ = true;
  return false;
}

Status StagedDirectory::commit() {
  if (committed_) return make_error(Error::Kind::internal, final_.string(), "already committed");
  std::error_code ec;
  // Move the previous output aside first: rename cannot replace a non-empty
  // directory, and keeping it until the swap succeeds allows a rollback.
  fs::path old;
  if (fs::exists(fs::symlink_status(final_))) {
    old = sibling(final_, "old");
    fs::rename(final_, old, ec);
    if (ec) return io_error(final_, "cannot move the previous output aside: " + ec.message());
  }
  fs::rename(staging_, final_, ec);
  if (ec) {
    std::error_code ignored;
    if (!old.empty()) fs::rename(old, final_, ignored);
    return io_error(final_, "cannot move the staged output into place: " + ec.message());
  }
  committed_ = true;
  if (!old.empty()) {
    fs::remove_all(old, ec);
    if (ec) return io_error(old, "output replaced, but the previous one remains: " + ec.message());
  }
  return {};
}

}  // namespace penumbra
