// Runs the built `penumbra` binary and captures its exit code and output.
#pragma once

#include <gtest/gtest.h>
#include <sys/types.h>

#include <filesystem>
#include <map>
#include <string>

#include "penumbra/support/image.hpp"

namespace penumbra::testing {

struct CliRun {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

// Whether a memory limit (`ulimit -v`) can bound the binary: not under
// AddressSanitizer, which reserves terabytes of address space at start.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PENUMBRA_TEST_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(PENUMBRA_TEST_ASAN)
inline constexpr bool kAddressSpaceCanBeLimited = false;
#else
inline constexpr bool kAddressSpaceCanBeLimited = true;
#endif

// `args` is appended to the binary's path as is (quote paths yourself);
// `env` ("NAME=value ...") is prepended to the command.
CliRun run_penumbra(const std::string& args, const std::string& env = "");

// Starts the binary like run_penumbra without waiting for it; its output
// is discarded. The process id, for kill() and wait_penumbra.
pid_t start_penumbra(const std::string& args, const std::string& env = "");

// Waits for a process of start_penumbra: its exit code, or -1 when a signal ended it.
int wait_penumbra(pid_t pid);

// Every regular file below `dir`, relative path -> bytes; empty when `dir`
// is missing. Two equal maps are the same tree.
std::map<std::string, std::string> read_tree(const std::filesystem::path& dir);

// A fresh empty directory under the test temp dir, removed by the destructor.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name);
  ~ScratchDir();
  const std::filesystem::path& path() const { return path_; }
  // Writes `text` to path()/name and returns the full path.
  std::filesystem::path write(const std::string& name, const std::string& text) const;
  // Number of entries below path(), recursively.
  std::size_t entry_count() const;

 private:
  std::filesystem::path path_;
};

// Sets or clears `path`'s immutable attribute (root only: a directory so
// marked takes no new file, even root's); whether it could.
bool set_immutable(const std::filesystem::path& path, bool on);

// Makes a directory take no new files while it lives, as a read-only mount
// or an installed folder does: immutable as root, whom permissions do not
// stop, without write permission otherwise. ok(): whether that worked here.
class ReadOnlyDir {
 public:
  explicit ReadOnlyDir(std::filesystem::path dir);
  ~ReadOnlyDir();
  ReadOnlyDir(const ReadOnlyDir&) = delete;
  ReadOnlyDir& operator=(const ReadOnlyDir&) = delete;
  bool ok() const { return ok_; }

 private:
  std::filesystem::path dir_;
  bool ok_ = false;
};

// The eval tests' fixture: a scratch directory holding the library `penumbra
// build` made from a manifest (lib/) and the first built-in scene's shadow
// map and receivers (depth.pfm, recv.pfm). Each suite calls set_up_eval() in
// SetUpTestSuite and tear_down_eval() in TearDownTestSuite.
class EvalFixture : public ::testing::Test {
 protected:
  static void set_up_eval(const std::string& name, const std::string& manifest);
  static void tear_down_eval();

  static std::filesystem::path lib() { return dir_->path() / "lib"; }
  // The scratch directory's `name`, quoted for run_penumbra.
  static std::string path(const std::string& name);
  // "eval <lib> <variant> --shadow-map depth.pfm --receivers recv.pfm <extra>".
  static std::string eval_args(const std::string& variant, const std::string& extra);
  // `device` within `tolerance` of `reference` at every pixel `marks` (the
  // reference's --ambiguous) leaves 0, which must be nine in ten, over a
  // scene with real penumbrae (500 pixels strictly between 0.01 and 0.99).
  static void expect_agreement(const FloatImage& device, const FloatImage& reference,
                               const FloatImage& marks, double tolerance);

  static inline ScratchDir* dir_ = nullptr;
  static inline FloatImage map_;
  static inline FloatImage receivers_;
};

}  // namespace penumbra::testing
