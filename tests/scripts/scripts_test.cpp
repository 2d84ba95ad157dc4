// A clone stands alone: no tracked file names a folder beside the checkout
// (CI runs with one there, so only this test sees the dependency come back),
// and the scripts that install and pack tools refuse bad input with exit 2
// and fail with one clear line, leaving what they made before as it was.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cli_harness.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::testing {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

const fs::path kSourceDir = PENUMBRA_SOURCE_DIR;

struct ScriptRun {
  int exit_code = -1;
  std::string out;  // stdout and stderr together
};

ScriptRun run(const std::string& command) {
  ScriptRun result;
  FILE* pipe = ::popen(("cd '" + kSourceDir.string() + "' && " + command + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) result.out.append(buffer, n);
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

TEST(Repository, NoTrackedFileNamesAFolderBesideTheCheckout) {
  if (!fs::exists(kSourceDir / ".git")) GTEST_SKIP() << "not a git checkout";
  const ScriptRun listed = run("git ls-files -z");
  ASSERT_EQ(listed.exit_code, 0) << listed.out;
  // Spelled in two pieces, so that this file does not name it either.
  const std::string sibling = std::string("..") + "/shared";
  std::string found;
  std::istringstream names(listed.out);
  for (std::string name; std::getline(names, name, '\0');) {
    if (name.empty()) continue;
    auto text = read_file(kSourceDir / name);
    if (!text) continue;  // a tracked file deleted in the work tree
    std::istringstream lines(*text);
    int number = 0;
    for (std::string line; std::getline(lines, line);) {
      ++number;
      if (line.find(sibling) != std::string::npos) {
        found += name + ":" + std::to_string(number) + ": " + line + "\n";
      }
    }
  }
  EXPECT_EQ(found, "") << "a user's clone has nothing beside it; these lines name " << sibling
                       << ":\n"
                       << found;
}

TEST(SidTools, RefusesAnUnknownToolNamingTheAllowedOnes) {
  const ScriptRun refused = run("bash scripts/lib/sid-tools.sh no-such-tool");
  EXPECT_EQ(refused.exit_code, 2) << refused.out;
  EXPECT_THAT(refused.out, HasSubstr("no-such-tool"));
  EXPECT_THAT(refused.out, HasSubstr("vkd3d"));
  EXPECT_THAT(refused.out, HasSubstr("tint"));
  EXPECT_THAT(refused.out, HasSubstr("dawn"));
}

TEST(SidTools, RefusesAnUnknownOption) {
  const ScriptRun refused = run("bash scripts/lib/sid-tools.sh vkd3d --no-such-option");
  EXPECT_EQ(refused.exit_code, 2) << refused.out;
  EXPECT_THAT(refused.out, HasSubstr("--no-such-option"));
}

// No archive answers (nothing listens on that loopback port): one error
// line, exit 1, and the earlier install in that folder is kept.
TEST(SidTools, SaysWhenNoArchiveAnswersAndKeepsTheEarlierInstall) {
  ScratchDir dir("sid-unreachable");
  fs::create_directories(dir.path() / "root");
  std::ofstream(dir.path() / "root" / "earlier") << "an earlier install";
  const ScriptRun failed =
      run("PENUMBRA_SID_URI=http://127.0.0.1:9/debian bash scripts/lib/sid-tools.sh "
          "tint --force --dir '" +
          dir.path().string() + "'");
  EXPECT_EQ(failed.exit_code, 1) << failed.out;
  EXPECT_THAT(failed.out, HasSubstr("sid-tools: error:"));
  EXPECT_THAT(failed.out, HasSubstr("127.0.0.1:9"));
  EXPECT_TRUE(fs::exists(dir.path() / "root" / "earlier"));
}

TEST(PackPortable, RefusesAFolderThatIsNotABuild) {
  ScratchDir dir("pack");
  const fs::path dest = dir.path() / "pack";
  fs::create_directories(dest);
  std::ofstream(dest / "earlier") << "an earlier pack";
  for (const fs::path& build : {dir.path() / "missing", dir.path() / "empty"}) {
    if (build.filename() == "empty") fs::create_directories(build);
    const ScriptRun refused =
        run("bash scripts/pack-portable.sh '" + build.string() + "' '" + dest.string() + "'");
    EXPECT_EQ(refused.exit_code, 2) << refused.out;
    EXPECT_THAT(refused.out, HasSubstr(build.string()));
    EXPECT_TRUE(fs::exists(dest / "earlier")) << build << " damaged the earlier pack";
  }
  const ScriptRun usage = run("bash scripts/pack-portable.sh");
  EXPECT_EQ(usage.exit_code, 2) << usage.out;
  EXPECT_THAT(usage.out, HasSubstr("usage: scripts/pack-portable.sh BUILD_DIR [DEST]"));
}

// The pack of this very build runs from its own folder: env.sh puts its
// penumbra first on PATH, with the libraries packed beside it.
TEST(PackPortable, PacksThisBuildSoThatItRunsFromThePack) {
  ScratchDir dir("pack-build");
  const fs::path dest = dir.path() / "pack";
  const ScriptRun packed = run("bash scripts/pack-portable.sh '" +
                               std::string(PENUMBRA_BINARY_DIR) + "' '" + dest.string() + "'");
  ASSERT_EQ(packed.exit_code, 0) << packed.out;
  EXPECT_THAT(packed.out, HasSubstr("packed "));
  EXPECT_FALSE(fs::exists(dir.path() / "pack.new"));
  const ScriptRun used = run("bash -c 'source \"" + dest.string() +
                             "/env.sh\" && command -v penumbra && penumbra --version'");
  EXPECT_EQ(used.exit_code, 0) << used.out;
  EXPECT_THAT(used.out, HasSubstr((dest / "bin" / "penumbra").string()));
  EXPECT_THAT(used.out, HasSubstr("penumbra " PENUMBRA_VERSION));
}

}  // namespace
}  // namespace penumbra::testing
