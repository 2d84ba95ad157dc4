// Atomic writes and staged directories. Both rely on rename() within one
// directory being atomic, so temporaries always live beside their target.
#include "penumbra/support/atomic_file.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <system_error>
#include <thread>
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

// `.<name>.<tag>`: a name beside `path`. Appended into one string: GCC 12's
// -Wrestrict misreads `"." + std::string` (an insert at the front) at -O3.
std::string hidden_name(const fs::path& path, std::string_view tag) {
  const std::string name = path.filename().string();
  std::string leaf;
  leaf.reserve(name.size() + tag.size() + 2);
  leaf.append(".").append(name).append(".").append(tag);
  return leaf;
}

// `.<name>.<tag>-<random>` beside `path`.
fs::path sibling(const fs::path& path, std::string_view tag) {
  return path.parent_path() / hidden_name(path, std::string(tag) + "-" + random_suffix());
}

// Whether `name` is what sibling(path, tag) makes.
bool is_sibling(const std::string& name, const fs::path& path, std::string_view tag) {
  const std::string prefix = hidden_name(path, std::string(tag) + "-");
  return name.size() == prefix.size() + 16 && name.starts_with(prefix) &&
         std::all_of(name.begin() + static_cast<std::ptrdiff_t>(prefix.size()), name.end(),
                     [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

Error io_error(const fs::path& path, std::string message) {
  return make_error(Error::Kind::io, path.string(), std::move(message));
}

}  // namespace

Status write_file_atomic(const fs::path& path, std::string_view bytes) {
  const fs::path temp = sibling(path, "tmp");
  if (Status written = write_file(temp, bytes); !written) {
    // e.g. "cannot create temporary file DIR/.v.pfm.tmp-…: Permission denied"
    std::string message = written.error().message;
    const std::string_view created = "cannot create the file";
    if (message.starts_with(created)) {
      message.replace(0, created.size(), "cannot create temporary file " + temp.string());
    } else {
      message = "temporary file " + temp.string() + ": " + message;
    }
    return io_error(path, std::move(message));
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

namespace {

// The file is removed on release, so a process may lock one that is no
// longer at `lock`: such a lock guards nothing, and it tries again.
Result<int> take_lock(const fs::path& target, const fs::path& lock) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
      return io_error(target,
                      "cannot create the lock file " + lock.string() + ": " + std::strerror(errno));
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      ::close(fd);
      if (error == EWOULDBLOCK) {
        return io_error(target, "another penumbra process is writing it (it holds " +
                                    lock.string() + "); try again when it finishes");
      }
      return io_error(target, "cannot lock " + lock.string() + ": " + std::strerror(error));
    }
    struct stat held {};
    struct stat named {};
    if (::fstat(fd, &held) == 0 && ::stat(lock.c_str(), &named) == 0 &&
        held.st_dev == named.st_dev && held.st_ino == named.st_ino) {
      return fd;
    }
    ::close(fd);
  }
  return io_error(target, "cannot lock " + lock.string() + ": it keeps being replaced");
}

// Removed before it is unlocked: whoever locks it next makes a new one.
void release_lock(const fs::path& lock, int fd) {
  ::unlink(lock.c_str());
  ::close(fd);
}

// Runs with the lock held, so no writer of `target` is alive to own what it
// removes. Only a commit by two renames stopped between them leaves an old
// tree without `target`, and that tree is the complete previous output.
// What cannot be removed now is tried again at the next create().
void clean_up_after_dead_writers(const fs::path& target) {
  std::vector<fs::path> old;
  std::vector<fs::path> stale;
  const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  for (auto it = fs::directory_iterator(parent, ec); !ec && it != fs::end(it); it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (is_sibling(name, target, "old")) old.push_back(it->path());
    if (is_sibling(name, target, "staging")) stale.push_back(it->path());
  }
  if (!old.empty() && !fs::exists(fs::symlink_status(target, ec))) {
    fs::rename(old.back(), target, ec);
    if (!ec) old.pop_back();
  }
  stale.insert(stale.end(), old.begin(), old.end());
  for (const fs::path& path : stale) fs::remove_all(path, ec);
}

}  // namespace

Result<StagedDirectory> StagedDirectory::create(const fs::path& final_dir) {
  const fs::path target = without_trailing_separator(final_dir);
  std::error_code ec;
  if (!target.parent_path().empty()) {
    fs::create_directories(target.parent_path(), ec);
    if (ec) return io_error(target, "cannot create parent directory: " + ec.message());
  }
  const fs::path lock = target.parent_path() / hidden_name(target, "lock");
  PENUMBRA_TRY_ASSIGN(const int lock_fd, take_lock(target, lock));
  clean_up_after_dead_writers(target);
  const fs::path staging = sibling(target, "staging");
  if (!fs::create_directory(staging, ec) || ec) {
    release_lock(lock, lock_fd);
    return io_error(target, "cannot create staging directory " + staging.string() +
                                (ec ? ": " + ec.message() : ": it already exists"));
  }
  return StagedDirectory(target, staging, lock_fd, lock);
}

StagedDirectory::StagedDirectory(fs::path final_dir, fs::path staging, int lock_fd, fs::path lock)
    : final_(std::move(final_dir)),
      staging_(std::move(staging)),
      lock_(std::move(lock)),
      lock_fd_(lock_fd) {}

StagedDirectory::StagedDirectory(StagedDirectory&& other) noexcept
    : final_(std::move(other.final_)),
      staging_(std::move(other.staging_)),
      lock_(std::move(other.lock_)),
      leftover_(std::move(other.leftover_)),
      lock_fd_(std::exchange(other.lock_fd_, -1)),
      committed_(std::exchange(other.committed_, true)) {}

StagedDirectory::~StagedDirectory() {
  if (!committed_ && !staging_.empty()) {
    std::error_code ignored;
    fs::remove_all(staging_, ignored);
  }
  unlock();
}

void StagedDirectory::unlock() {
  if (lock_fd_ >= 0) release_lock(lock_, std::exchange(lock_fd_, -1));
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
  unlock();
  return false;
}

namespace {

// A kill test's window between commit()'s steps (PENUMBRA_TEST_COMMIT_DELAY_MS).
void pause_for_tests() {
  static const long delay_ms = [] {
    const char* text = std::getenv("PENUMBRA_TEST_COMMIT_DELAY_MS");
    return text ? std::strtol(text, nullptr, 10) : 0L;
  }();
  if (delay_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
}

// Swaps two directory entries in one step, so that no crash can leave
// neither: Linux's renameat2. not_supported where the file system lacks it.
std::error_code exchange(const fs::path& a, const fs::path& b) {
#ifdef RENAME_EXCHANGE
  if (::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0) return {};
  if (errno != EINVAL && errno != ENOSYS) return {errno, std::generic_category()};
#endif
  return std::make_error_code(std::errc::not_supported);
}

// Without exchange(): `target` aside first, as rename cannot replace a
// non-empty directory, then `staging` into its place. A kill between the two
// leaves no `target`; the next create() puts the old tree back. Where the
// old tree is.
Result<fs::path> replace_by_renames(const fs::path& staging, const fs::path& target) {
  const fs::path old = sibling(target, "old");
  std::error_code ec;
  fs::rename(target, old, ec);
  if (ec) return io_error(target, "cannot move the previous output aside: " + ec.message());
  pause_for_tests();
  fs::rename(staging, target, ec);
  if (ec) {
    std::error_code ignored;
    fs::rename(old, target, ignored);
    return io_error(target, "cannot move the staged output into place: " + ec.message());
  }
  return old;
}

}  // namespace

Status StagedDirectory::commit() {
  if (committed_) return make_error(Error::Kind::internal, final_.string(), "already committed");
  pause_for_tests();
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(final_, ec))) {
    fs::rename(staging_, final_, ec);
    if (ec) return io_error(final_, "cannot move the staged output into place: " + ec.message());
    committed_ = true;
    unlock();
    return {};
  }
  fs::path previous = staging_;
  if (ec = exchange(staging_, final_); ec == std::errc::not_supported) {
    PENUMBRA_TRY_ASSIGN(previous, replace_by_renames(staging_, final_));
  } else if (ec) {
    return io_error(final_, "cannot swap the staged output into place: " + ec.message());
  }
  // The new tree is in place: what follows cannot fail the commit.
  committed_ = true;
  pause_for_tests();
  fs::remove_all(previous, ec);
  if (ec) leftover_ = previous;
  unlock();
  return {};
}

}  // namespace penumbra
