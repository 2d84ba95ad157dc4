// `penumbra build`'s shader cache, build stamps and split builds, run on
// the real executable: cached output is byte for byte the uncached one, an
// unchanged rebuild does nothing, a shaderlib edit recompiles only the
// shaders that include it, and --group parts merge into the whole build.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>

#include "cli_harness.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::testing {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

// Five cheap variants of two techniques, for spirv and glsl330.
constexpr const char* kManifest =
    R"({"schema": 1, "targets": ["spirv", "glsl330"],)"
    R"( "sets": [{"technique": "hard"}, {"technique": "pcf_grid", "kernel": [3, 5]},)"
    R"( {"technique": "pcf_poisson", "pcf_samples": [4, 8], "disk": "whitepaper16"}]})";

// Every file under `root`, relative path -> bytes.
std::map<std::string, std::string> tree(const fs::path& root) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    files[entry.path().lexically_relative(root).string()] = read_file(entry.path()).value();
  }
  return files;
}

// "N shaders from the cache" of a build's summary line.
int from_cache(const CliRun& run) {
  std::smatch match;
  if (!std::regex_search(run.out, match, std::regex("([0-9]+) shaders from the cache"))) return -1;
  return std::stoi(match[1]);
}

class BuildCache : public ::testing::Test {
 protected:
  ScratchDir dir{"build-cache"};
  fs::path manifest = dir.write("manifest.json", kManifest);

  CliRun build(const fs::path& out, const std::string& flags = "") {
    return run_penumbra("build '" + manifest.string() + "' -o '" + out.string() +
                            "' --cache-dir '" + (dir.path() / "cache").string() + "' " + flags,
                        "PENUMBRA_HLSL_COMPILER=");
  }
};

TEST_F(BuildCache, CachedOutputIsTheUncachedOutput) {
  const CliRun cold = build(dir.path() / "cold");
  ASSERT_EQ(cold.exit_code, 0) << cold.err;
  EXPECT_EQ(from_cache(cold), 0) << cold.out;
  const CliRun warm = build(dir.path() / "warm");
  ASSERT_EQ(warm.exit_code, 0) << warm.err;
  EXPECT_GT(from_cache(warm), 0) << warm.out;
  EXPECT_THAT(warm.out, HasSubstr("shader files, 0 bytecode files, " +
                                  std::to_string(from_cache(warm)) + " shaders"));
  const CliRun none = build(dir.path() / "none", "--no-cache");
  ASSERT_EQ(none.exit_code, 0) << none.err;
  EXPECT_EQ(tree(dir.path() / "warm"), tree(dir.path() / "cold"));
  EXPECT_EQ(tree(dir.path() / "none"), tree(dir.path() / "cold"));
}

TEST_F(BuildCache, UnchangedRebuildDoesNothing) {
  const fs::path out = dir.path() / "out";
  ASSERT_EQ(build(out).exit_code, 0);
  const auto written = fs::last_write_time(out / "index.json");
  const CliRun again = build(out);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_THAT(again.out, HasSubstr("is up to date"));
  EXPECT_EQ(fs::last_write_time(out / "index.json"), written);

  // Output that someone else touched is rebuilt (from the cache).
  std::ofstream(out / "index.json", std::ios::app) << " ";
  const CliRun touched = build(out);
  ASSERT_EQ(touched.exit_code, 0) << touched.err;
  EXPECT_THAT(touched.out, HasSubstr("built 5 variants"));
  // So is a build with other options.
  EXPECT_THAT(build(out, "--target spirv").out, HasSubstr("built 5 variants"));
}

// A build in fewer forms is not the build before it, and every shader it
// needs is one the build in every form cached: the cache keys no form.
TEST_F(BuildCache, AnotherFormIsRebuiltFromTheCache) {
  const fs::path out = dir.path() / "out";
  ASSERT_EQ(build(out).exit_code, 0);
  const CliRun function = build(out, "--form function");
  ASSERT_EQ(function.exit_code, 0) << function.err;
  EXPECT_THAT(function.out, HasSubstr("built 5 variants"));
  std::smatch files;
  ASSERT_TRUE(std::regex_search(function.out, files, std::regex("([0-9]+) shader files")))
      << function.out;
  EXPECT_EQ(from_cache(function), std::stoi(files[1])) << function.out;
  EXPECT_THAT(read_file(out / "index.json").value(), Not(HasSubstr("query.frag")));
  EXPECT_THAT(build(out, "--form function").out, HasSubstr("is up to date"));
}

TEST_F(BuildCache, ShaderlibEditRecompilesOnlyTheShadersThatIncludeIt) {
  const fs::path shaderlib = dir.path() / "shaderlib";
  fs::copy(PENUMBRA_SOURCE_SHADERLIB, shaderlib, fs::copy_options::recursive);
  const fs::path out = dir.path() / "out";
  const std::string flags = "--shaderlib '" + shaderlib.string() + "'";
  const CliRun cold = build(out, flags);
  ASSERT_EQ(cold.exit_code, 0) << cold.err;
  std::smatch match;
  ASSERT_TRUE(std::regex_search(cold.out, match, std::regex("\\(([0-9]+) shader files")));
  const int shaders = std::stoi(match[1]);

  // pcf_grid's two variants: their query and deferred fragment shaders per
  // target, and one function form each for glsl330.
  std::ofstream(shaderlib / "techniques/pcf_grid.glsl", std::ios::app)
      << "\nfloat penumbra_test_unused_helper(float x) { return x * 2.0 + 1.0; }\n";
  const CliRun edited = build(out, flags);
  ASSERT_EQ(edited.exit_code, 0) << edited.err;
  EXPECT_EQ(from_cache(edited), shaders - 10) << edited.out;
}

TEST_F(BuildCache, GroupsMergeIntoTheWholeBuild) {
  ASSERT_EQ(build(dir.path() / "whole").exit_code, 0);
  std::string parts;
  std::size_t variants = 0;
  for (int group = 1; group <= 7; ++group) {  // more groups than variants: some are empty
    const fs::path part = dir.path() / ("part" + std::to_string(group));
    const CliRun run = build(part, "--group " + std::to_string(group) + "/7");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::smatch match;
    ASSERT_TRUE(std::regex_search(run.out, match, std::regex("built ([0-9]+) variants")));
    variants += std::stoul(match[1]);
    parts += " '" + part.string() + "'";
  }
  EXPECT_EQ(variants, 5u);
  const fs::path merged = dir.path() / "merged";
  const CliRun merge = run_penumbra("merge" + parts + " -o '" + merged.string() + "'");
  ASSERT_EQ(merge.exit_code, 0) << merge.err;
  EXPECT_THAT(merge.out, HasSubstr("merged 7 parts: 5 variants"));
  EXPECT_EQ(tree(merged), tree(dir.path() / "whole"));
}

TEST_F(BuildCache, AGroupWhoseVariantsDidNotChangeKeepsItsPart) {
  const fs::path part = dir.path() / "part";
  // Find the group of pcf_grid_k3 among 7 and keep only groups without it.
  for (int group = 1; group <= 7; ++group) {
    fs::remove_all(part);
    ASSERT_EQ(build(part, "--group " + std::to_string(group) + "/7").exit_code, 0);
    if (read_file(part / "index.json").value().find("pcf_grid_k3") != std::string::npos) continue;
    const auto written = fs::last_write_time(part / "index.json");
    // Another set of the manifest changes: pcf_grid_k3 goes, k7 comes.
    std::string edited = kManifest;
    edited.replace(edited.find("[3, 5]"), 6, "[5, 7]");
    manifest = dir.write("manifest.json", edited);
    const CliRun run = build(part, "--group " + std::to_string(group) + "/7");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    if (read_file(part / "index.json").value().find("pcf_grid_k7") != std::string::npos) {
      manifest = dir.write("manifest.json", kManifest);
      continue;  // the new variant landed in this group: try another
    }
    EXPECT_THAT(run.out, HasSubstr("is up to date"));
    EXPECT_EQ(fs::last_write_time(part / "index.json"), written);
    return;
  }
  FAIL() << "no group without pcf_grid_k3 and k7";
}

TEST_F(BuildCache, BadGroupsAndOverlappingPartsAreBadInput) {
  for (const char* group : {"0/3", "4/3", "3", "1/0", "a/b", "1/5000"}) {
    const CliRun run = build(dir.path() / "out", std::string("--group ") + group);
    EXPECT_EQ(run.exit_code, 2) << group;
    EXPECT_THAT(run.err, HasSubstr(std::string("--group ") + group + ": expected I/N"));
    EXPECT_FALSE(fs::exists(dir.path() / "out"));
  }
  ASSERT_EQ(build(dir.path() / "whole").exit_code, 0);
  const std::string whole = "'" + (dir.path() / "whole").string() + "'";
  const CliRun twice = run_penumbra("merge " + whole + " " + whole + " -o '" +
                                    (dir.path() / "merged").string() + "'");
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_THAT(twice.err, HasSubstr("is also in"));
  EXPECT_FALSE(fs::exists(dir.path() / "merged"));
  const CliRun not_a_library = run_penumbra("merge '" + dir.path().string() + "/nothing' -o '" +
                                            (dir.path() / "merged").string() + "'");
  EXPECT_EQ(not_a_library.exit_code, 2);
  EXPECT_FALSE(fs::exists(dir.path() / "merged"));
}

}  // namespace
}  // namespace penumbra::testing
