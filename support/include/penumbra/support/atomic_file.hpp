// Writing output without leaving partial results behind.
#pragma once

#include <filesystem>
#include <string_view>

#include "penumbra/support/result.hpp"

namespace penumbra {

// Writes `bytes` to a temporary file beside `path`, then renames it over `path`.
Status write_file_atomic(const std::filesystem::path& path, std::string_view bytes);

// A staging directory beside a final output directory: everything is written
// into staging(), and commit() swaps it into place. If commit() is never
// called, the destructor removes the staging directory, so a failed build
// leaves the final directory untouched.
//
// One writer at a time: from create() until it has committed or is
// destroyed, a StagedDirectory holds an exclusive lock on `.NAME.lock` beside
// the final directory NAME (removed when released), and create() fails while
// another holds it.
//
// Test-only: PENUMBRA_TEST_COMMIT_DELAY_MS=N makes commit() sleep N ms before
// and after each step, so that a test can kill a writer between them.
class StagedDirectory {
 public:
  // Takes the lock, then cleans up after writers that died: when final_dir is
  // missing but a commit moved its previous tree aside, puts that back; then
  // removes every other staging and previous tree of theirs.
  static Result<StagedDirectory> create(const std::filesystem::path& final_dir);
  StagedDirectory(StagedDirectory&& other) noexcept;
  StagedDirectory& operator=(StagedDirectory&&) = delete;
  StagedDirectory(const StagedDirectory&) = delete;
  ~StagedDirectory();

  const std::filesystem::path& staging() const { return staging_; }
  // Replaces final_dir with the staged tree: one atomic exchange where the
  // file system has it (renameat2), else two renames. Succeeds once the
  // staged tree is in place, even when the previous one cannot be removed
  // (see leftover()).
  Status commit();
  // Like commit(), unless final_dir already holds the same files with the
  // same bytes: then the staged tree is dropped and final_dir keeps its
  // times, so build systems that compare them (Ninja's restat) rebuild
  // nothing downstream. Whether final_dir was replaced.
  Result<bool> commit_if_changed();
  // Where the tree that commit() replaced still is because it could not be
  // removed (empty when none): the next create() for final_dir tries again.
  const std::filesystem::path& leftover() const { return leftover_; }

 private:
  StagedDirectory(std::filesystem::path final_dir, std::filesystem::path staging, int lock_fd,
                  std::filesystem::path lock);
  void unlock();
  std::filesystem::path final_;
  std::filesystem::path staging_;
  std::filesystem::path lock_;
  std::filesystem::path leftover_;
  int lock_fd_ = -1;
  bool committed_ = false;
};

}  // namespace penumbra
