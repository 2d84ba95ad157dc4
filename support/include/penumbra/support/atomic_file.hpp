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
class StagedDirectory {
 public:
  static Result<StagedDirectory> create(const std::filesystem::path& final_dir);
  StagedDirectory(StagedDirectory&& other) noexcept;
  StagedDirectory& operator=(StagedDirectory&&) = delete;
  StagedDirectory(const StagedDirectory&) = delete;
  ~StagedDirectory();

  const std::filesystem::path& staging() const { return staging_; }
  // Replaces final_dir with the staged tree.
  Status commit();
  // Like commit(), unless final_dir already holds the same files with the
  // same bytes: then the staged tree is dropped and final_dir keeps its
  // times, so build systems that compare them (Ninja's restat) rebuild
  // nothing downstream. Whether final_dir was replaced.
  Result<bool> commit_if_changed();

 private:
  StagedDirectory(std::filesystem::path final_dir, std::filesystem::path staging);
  std::filesystem::path final_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

}  // namespace penumbra
