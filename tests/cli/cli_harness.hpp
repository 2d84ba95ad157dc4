// Runs the built `penumbra` binary and captures its exit code and output.
#pragma once

#include <filesystem>
#include <string>

namespace penumbra::testing {

struct CliRun {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

// `args` is appended to the binary's path as is (quote paths yourself);
// `env` ("NAME=value ...") is prepended to the command.
CliRun run_penumbra(const std::string& args, const std::string& env = "");

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

}  // namespace penumbra::testing
