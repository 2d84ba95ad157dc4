// `penumbra build` killed with SIGKILL at random moments, commit included:
// OUT must always be the complete previous library or the complete new one,
// and the next build must succeed and leave nothing beside OUT.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <random>
#include <thread>

#include "cli_harness.hpp"

namespace penumbra::testing {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kManifests[2] = {
    R"({"schema": 1, "targets": ["spirv"], "sets": [{"technique": ["hard"]}]})",
    R"({"schema": 1, "targets": ["spirv"], "sets": [{"technique": ["pcf_grid"], "kernel": [3]}]})"};
constexpr int kKills = 24;
// Test-only: how long the commit pauses before and after its swap, so that
// kills land between its steps too.
constexpr int kCommitDelayMs = 150;

// The names beside `out` that start with "." + its name: staging, old trees, locks.
std::vector<std::string> siblings(const fs::path& out) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(out.parent_path())) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with("." + out.filename().string())) names.push_back(name);
  }
  return names;
}

TEST(KilledBuild, LeavesTheOldOrTheNewLibraryAndTheNextBuildCleansUp) {
  const ScratchDir dir("killed-build");
  const std::string home = (dir.path() / "home").string();
  const std::string env =
      "HOME='" + home + "' XDG_CACHE_HOME='" + home + "/cache' PENUMBRA_HLSL_COMPILER=";
  auto args = [&](int manifest, const fs::path& out) {
    const auto file = dir.write("m" + std::to_string(manifest) + ".json", kManifests[manifest]);
    return "build '" + file.string() + "' -o '" + out.string() + "'";
  };
  // Each manifest's library, built undisturbed (and the shader cache warmed).
  std::map<std::string, std::string> trees[2];
  for (int m : {0, 1}) {
    const fs::path ref = dir.path() / ("ref" + std::to_string(m));
    const CliRun run = run_penumbra(args(m, ref), env);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    trees[m] = read_tree(ref);
    ASSERT_TRUE(trees[m].contains("index.json"));
  }
  ASSERT_TRUE(trees[0] != trees[1]);

  const fs::path out = dir.path() / "out";
  ASSERT_EQ(run_penumbra(args(0, out), env).exit_code, 0);
  // How long a build with the widened commit takes: the kills fall within it.
  const std::string delay_env =
      env + " PENUMBRA_TEST_COMMIT_DELAY_MS=" + std::to_string(kCommitDelayMs);
  const auto start = Clock::now();
  ASSERT_EQ(run_penumbra(args(1, out), delay_env).exit_code, 0);
  const auto span = std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - start);
  int current = 1;

  const char* seed_text = std::getenv("PENUMBRA_KILL_TEST_SEED");
  const unsigned seed =
      seed_text ? static_cast<unsigned>(std::strtoul(seed_text, nullptr, 10)) : 20240613u;
  std::cout << "seed " << seed << " (PENUMBRA_KILL_TEST_SEED), kills within " << span.count() / 1000
            << " ms\n";
  std::mt19937 random(seed);
  int outcomes[2] = {0, 0};  // old, new
  for (int kill = 0; kill < kKills; ++kill) {
    const int next = 1 - current;
    // Spread evenly over the build's span, with a random place in each slice.
    const double slice = std::uniform_real_distribution<double>(0.0, 1.0)(random);
    const auto at = std::chrono::microseconds(
        static_cast<long long>(static_cast<double>(span.count()) * (kill + slice) / kKills));
    const pid_t pid = start_penumbra(args(next, out), delay_env);
    std::this_thread::sleep_for(at);
    ::kill(pid, SIGKILL);
    const int exit_code = wait_penumbra(pid);

    const auto tree = read_tree(out);
    const bool old_tree = tree == trees[current];
    const bool new_tree = tree == trees[next];
    std::cout << "kill " << kill << " at " << at.count() / 1000
              << " ms: " << (exit_code == -1 ? "killed" : "had exited") << ", OUT is the "
              << (old_tree   ? "old"
                  : new_tree ? "new"
                             : "BROKEN")
              << " library, " << siblings(out).size() << " entries beside it\n";
    ASSERT_TRUE(old_tree || new_tree)
        << "kill " << kill << " at " << at.count() << " us (seed " << seed << ") left "
        << tree.size() << " files in OUT, neither library";
    ++outcomes[new_tree ? 1 : 0];

    // The next build finishes the job and removes what the killed one left.
    const CliRun after = run_penumbra(args(next, out), env);
    ASSERT_EQ(after.exit_code, 0) << "after kill " << kill << ": " << after.err;
    ASSERT_TRUE(read_tree(out) == trees[next]) << "after kill " << kill;
    ASSERT_EQ(siblings(out), std::vector<std::string>{}) << "after kill " << kill;
    current = next;
  }
  std::cout << outcomes[0] << " kills left the old library, " << outcomes[1] << " the new one\n";
}

}  // namespace
}  // namespace penumbra::testing
