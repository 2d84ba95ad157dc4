// What `penumbra build` and `merge` may do to OUT and what lies beside it:
// replace only a library that penumbra wrote, one writer at a time, clean up
// after writers that died, and exit 0 once OUT is replaced.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <optional>
#include <thread>

#include "cli_harness.hpp"

namespace penumbra::testing {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

constexpr const char* kHard =
    R"({"schema": 1, "targets": ["spirv"], "sets": [{"technique": ["hard"]}]})";
constexpr const char* kPcf =
    R"({"schema": 1, "targets": ["spirv"], "sets": [{"technique": ["pcf_grid"], "kernel": [3]}]})";

class OutputSafety : public ::testing::Test {
 protected:
  ScratchDir dir{"output-safety"};

  // The environment of every run: a cache of this test's own, no HLSL compiler.
  std::string env() const {
    const std::string home = (dir.path() / "home").string();
    return "HOME='" + home + "' XDG_CACHE_HOME='" + home + "/cache' PENUMBRA_HLSL_COMPILER=";
  }
  std::string build_args(const char* manifest, const std::string& flags) const {
    const auto file = dir.write(manifest == kHard ? "hard.json" : "pcf.json", manifest);
    return "build '" + file.string() + "' -o '" + out().string() + "' " + flags;
  }
  CliRun build(const char* manifest, const std::string& flags = "") const {
    return run_penumbra(build_args(manifest, flags), env());
  }
  fs::path out() const { return dir.path() / "out"; }

  // The names beside out/ that start with ".out": staging, old trees, locks.
  std::vector<std::string> siblings() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir.path())) {
      const std::string name = entry.path().filename().string();
      if (name.starts_with(".out")) names.push_back(name);
    }
    return names;
  }
};

// A folder with an index.json that penumbra did not write is a user's: it
// stays as it was, and nothing is written beside it.
TEST_F(OutputSafety, AFolderThatIsNotALibraryIsRefusedAndLeftUntouched) {
  const CliRun part = run_penumbra("build '" + dir.write("hard.json", kHard).string() +
                                       "' --group 1/1 -o '" + (dir.path() / "part").string() + "'",
                                   env());
  ASSERT_EQ(part.exit_code, 0) << part.err;
  for (const char* index :
       {R"({"name": "my notes"})", "not json at all", "",
        R"({"generator": "someone else", "schema": 3})", R"([{"generator": "penumbra 0.1.0"}])"}) {
    SCOPED_TRACE(index);
    fs::create_directories(out());
    dir.write("out/index.json", index);
    dir.write("out/notes.txt", "keep me");
    const auto before = read_tree(out());
    for (const std::string& command :
         {build_args(kHard, ""),
          "merge '" + (dir.path() / "part").string() + "' -o '" + out().string() + "'"}) {
      const CliRun run = run_penumbra(command, env());
      EXPECT_EQ(run.exit_code, 2) << command;
      EXPECT_THAT(run.err, HasSubstr("-o " + out().string()));
      EXPECT_THAT(run.err, HasSubstr("not a penumbra library"));
      EXPECT_THAT(run.err, HasSubstr("allowed:"));
      EXPECT_TRUE(read_tree(out()) == before) << "OUT changed";
      EXPECT_EQ(siblings(), std::vector<std::string>{});
    }
  }
}

TEST_F(OutputSafety, ALibraryThatPenumbraWroteIsReplaced) {
  ASSERT_EQ(build(kHard).exit_code, 0);
  const CliRun run = build(kPcf);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(read_tree(out()).at("index.json"), HasSubstr("pcf_grid"));
  EXPECT_EQ(siblings(), std::vector<std::string>{});
}

// While one build stages into OUT, a second one into the same OUT is refused
// and changes nothing; the first then finishes as if alone.
TEST_F(OutputSafety, ASecondBuildIntoTheSameOutputIsRefused) {
  ASSERT_EQ(build(kHard).exit_code, 0);
  const pid_t first =
      start_penumbra(build_args(kPcf, ""), env() + " PENUMBRA_TEST_COMMIT_DELAY_MS=3000");
  // Its staging directory appears once it holds OUT.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  auto staging = [&] {
    for (const std::string& name : siblings()) {
      if (name.starts_with(".out.staging-")) return true;
    }
    return false;
  };
  while (!staging() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_TRUE(staging()) << "the first build never staged";
  const CliRun second = build(kPcf, "--no-cache");
  EXPECT_EQ(second.exit_code, 2);
  EXPECT_THAT(second.err, HasSubstr(out().string()));
  EXPECT_THAT(second.err, HasSubstr("another penumbra process is writing"));
  EXPECT_THAT(second.err, HasSubstr("try again when it finishes"));
  EXPECT_EQ(wait_penumbra(first), 0);
  EXPECT_THAT(read_tree(out()).at("index.json"), HasSubstr("pcf_grid"));
  EXPECT_EQ(siblings(), std::vector<std::string>{});
}

// A build killed before or during its commit leaves its staging tree, or the
// previous tree moved aside; the next build into OUT removes them.
TEST_F(OutputSafety, WhatAKilledBuildLeftIsRemovedByTheNext) {
  ASSERT_EQ(build(kHard).exit_code, 0);
  for (const char* name : {".out.staging-0123456789abcdef", ".out.old-fedcba9876543210"}) {
    fs::create_directories(dir.path() / name / "sub");
    dir.write(std::string(name) + "/sub/index.json", "stale");
  }
  const CliRun run = build(kPcf);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(read_tree(out()).at("index.json"), HasSubstr("pcf_grid"));
  EXPECT_EQ(siblings(), std::vector<std::string>{});
}

// A --depfile that cannot be written fails the build before it starts, not
// after OUT was replaced.
TEST_F(OutputSafety, AnUnwritableDepfileIsRefusedBeforeOutIsReplaced) {
  ASSERT_EQ(build(kHard).exit_code, 0);
  const auto before = read_tree(out());
  for (const fs::path& depfile : {dir.path() / "missing" / "out.d", dir.path()}) {
    const CliRun run = build(kPcf, "--depfile '" + depfile.string() + "'");
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_THAT(run.err, HasSubstr("--depfile " + depfile.string()));
    EXPECT_THAT(run.err, HasSubstr("allowed:"));
    EXPECT_TRUE(read_tree(out()) == before) << "OUT changed";
    EXPECT_EQ(siblings(), std::vector<std::string>{});
  }
}

// Makes files under a directory undeletable (immutable as root, a read-only
// directory otherwise) and, when destroyed, deletable again.
class Undeletable {
 public:
  explicit Undeletable(fs::path root) : root_(std::move(root)) {}
  ~Undeletable() {
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(root_, ec); !ec && it != fs::end(it);
         it.increment(ec)) {
      if (it->is_directory()) fs::permissions(it->path(), fs::perms::owner_all, ec);
      if (it->is_regular_file()) set_immutable(it->path(), false);
    }
  }
  Undeletable(const Undeletable&) = delete;
  Undeletable& operator=(const Undeletable&) = delete;

  // Whether `dir`'s file `name` could be made undeletable.
  static bool make(const fs::path& dir, const fs::path& file) {
    if (::geteuid() == 0) return set_immutable(file, true);
    std::error_code ec;
    fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec, ec);
    return !ec;
  }

 private:
  fs::path root_;
};

// Once OUT is replaced the build has succeeded: a previous tree that cannot be
// deleted is a warning, and the next build tries again.
TEST_F(OutputSafety, APreviousTreeThatCannotBeDeletedIsAWarningNotAFailure) {
  ASSERT_EQ(build(kHard).exit_code, 0);
  fs::create_directories(out() / "kept");
  const auto file = dir.write("out/kept/file.txt", "cannot delete me");
  std::optional<Undeletable> guard(dir.path());
  if (!Undeletable::make(out() / "kept", file)) GTEST_SKIP() << "cannot make a file undeletable";
  const CliRun run = build(kPcf);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.err, HasSubstr("warning"));
  EXPECT_THAT(run.err, HasSubstr("the next build"));
  EXPECT_THAT(read_tree(out()).at("index.json"), HasSubstr("pcf_grid"));
  EXPECT_EQ(read_tree(out()).count("kept/file.txt"), 0u);

  guard.reset();
  ASSERT_EQ(build(kHard).exit_code, 0);
  EXPECT_EQ(siblings(), std::vector<std::string>{});
}

}  // namespace
}  // namespace penumbra::testing
