#include "cli_harness.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <linux/fs.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

#include "penumbra/reference/scene.hpp"
#include "penumbra/support/pfm.hpp"

namespace penumbra::testing {
namespace {

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

bool set_immutable(const std::filesystem::path& path, bool on) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  int flags = 0;
  bool done = ::ioctl(fd, FS_IOC_GETFLAGS, &flags) == 0;
  flags = on ? (flags | FS_IMMUTABLE_FL) : (flags & ~FS_IMMUTABLE_FL);
  done = done && ::ioctl(fd, FS_IOC_SETFLAGS, &flags) == 0;
  ::close(fd);
  return done;
}

ReadOnlyDir::ReadOnlyDir(std::filesystem::path dir) : dir_(std::move(dir)) {
  namespace fs = std::filesystem;
  if (::geteuid() == 0) {
    ok_ = set_immutable(dir_, true);
  } else {
    std::error_code ec;
    fs::permissions(dir_, fs::perms::owner_write, fs::perm_options::remove, ec);
    ok_ = !ec;
  }
}

ReadOnlyDir::~ReadOnlyDir() {
  if (!ok_) return;
  if (::geteuid() == 0) {
    set_immutable(dir_, false);
  } else {
    std::error_code ec;
    std::filesystem::permissions(dir_, std::filesystem::perms::owner_write,
                                 std::filesystem::perm_options::add, ec);
  }
}

CliRun run_penumbra(const std::string& args, const std::string& env) {
  const auto base =
      std::filesystem::path(::testing::TempDir()) / ("penumbra-cli-" + std::to_string(::getpid()));
  const std::string out = base.string() + ".out";
  const std::string err = base.string() + ".err";
  const std::string command = env + " " + std::string(PENUMBRA_EXECUTABLE) + " " + args + " > '" +
                              out + "' 2> '" + err + "'";
  const int status = std::system(command.c_str());
  CliRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = slurp(out);
  run.err = slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return run;
}

pid_t start_penumbra(const std::string& args, const std::string& env) {
  // exec env: the shell becomes penumbra, so the pid is penumbra's own.
  const std::string command =
      "exec env " + env + " " + std::string(PENUMBRA_EXECUTABLE) + " " + args + " >/dev/null 2>&1";
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

int wait_penumbra(pid_t pid) {
  int status = 0;
  if (::waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::map<std::string, std::string> read_tree(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  std::error_code ec;
  for (auto it = std::filesystem::recursive_directory_iterator(dir, ec);
       !ec && it != std::filesystem::end(it); it.increment(ec)) {
    if (it->is_regular_file()) {
      files[it->path().lexically_relative(dir).string()] = slurp(it->path());
    }
  }
  return files;
}

ScratchDir::ScratchDir(const std::string& name)
    : path_(std::filesystem::path(::testing::TempDir()) /
            ("penumbra-" + name + "-" + std::to_string(::getpid()))) {
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

std::filesystem::path ScratchDir::write(const std::string& name, const std::string& text) const {
  const auto file = path_ / name;
  std::ofstream(file) << text;
  return file;
}

std::size_t ScratchDir::entry_count() const {
  std::size_t count = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::recursive_directory_iterator(path_)) {
    ++count;
  }
  return count;
}

void EvalFixture::set_up_eval(const std::string& name, const std::string& manifest) {
  dir_ = new ScratchDir(name);
  const auto manifest_file = dir_->write("manifest.json", manifest);
  const CliRun run =
      run_penumbra("build '" + manifest_file.string() + "' -o '" + lib().string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // The NVIDIA PCSS whitepaper's own setting: its constants are the scenes' defaults.
  const reference::Scene scene = reference::builtin_scenes().front();
  map_ = reference::ray_cast_depth(scene, scene.map_width, scene.map_height, scene.far_z);
  receivers_ = reference::receivers(scene, scene.receivers_width, scene.receivers_height);
  ASSERT_TRUE(write_pfm(dir_->path() / "depth.pfm", map_).ok());
  ASSERT_TRUE(write_pfm(dir_->path() / "recv.pfm", receivers_).ok());
}

void EvalFixture::tear_down_eval() {
  delete dir_;
  dir_ = nullptr;
}

std::string EvalFixture::path(const std::string& name) {
  return "'" + (dir_->path() / name).string() + "'";
}

void EvalFixture::expect_agreement(const FloatImage& device, const FloatImage& reference,
                                   const FloatImage& marks, double tolerance) {
  ASSERT_EQ(device.data.size(), reference.data.size());
  ASSERT_EQ(marks.data.size(), reference.data.size());
  std::size_t compared = 0, partial = 0;
  for (std::size_t p = 0; p < device.data.size(); ++p) {
    if (marks.data[p] != 0.0f) continue;
    ASSERT_NEAR(device.data[p], reference.data[p], tolerance) << "pixel " << p;
    ++compared;
    partial += reference.data[p] > 0.01f && reference.data[p] < 0.99f;
  }
  EXPECT_GT(compared, device.data.size() * 9 / 10);
  EXPECT_GT(partial, 500u) << "the scene must have real penumbrae";
}

std::string EvalFixture::eval_args(const std::string& variant, const std::string& extra) {
  return "eval '" + lib().string() + "' " + variant + " --shadow-map " + path("depth.pfm") +
         " --receivers " + path("recv.pfm") + " " + extra;
}

}  // namespace penumbra::testing
