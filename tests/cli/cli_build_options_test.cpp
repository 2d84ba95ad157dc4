// `penumbra build`'s everyday options, run on the real executable: -j's
// default, -q, --keep-going, and the --variant, --target and --form filters.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "cli_harness.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// Three cheap variants, for spirv and hlsl_dx10.
constexpr const char* kManifest =
    R"({"schema": 1, "targets": ["spirv", "hlsl_dx10"],)"
    R"( "sets": [{"technique": ["hard"]}, {"technique": ["pcf_grid"], "kernel": [3, 5]}]})";

class BuildOptions : public ::testing::Test {
 protected:
  ScratchDir dir{"build-options"};

  // `penumbra build` of kManifest into out/ with `flags`, and no HLSL compiler
  // unless `flags` names one.
  CliRun build(const std::string& flags) {
    const auto manifest = dir.write("manifest.json", kManifest);
    const std::string home = (dir.path() / "home").string();
    return run_penumbra(
        "build '" + manifest.string() + "' -o '" + out().string() + "' " + flags,
        "HOME='" + home + "' XDG_CACHE_HOME='" + home + "/cache' " + "PENUMBRA_HLSL_COMPILER=");
  }
  std::filesystem::path out() const { return dir.path() / "out"; }

  // The variant names and targets of out/index.json.
  std::vector<std::string> built_variants() const {
    std::ifstream in(out() / "index.json");
    const auto index = nlohmann::json::parse(in);
    std::vector<std::string> names;
    for (const auto& variant : index.at("variants")) names.push_back(variant.at("name"));
    return names;
  }

  // An "HLSL compiler" that fails every file, saying which.
  std::string failing_compiler() const {
    const auto script = dir.write("failing-compiler.sh",
                                  "#!/bin/sh\nfor a; do last=$a; done\n"
                                  "echo \"$last:1:1: E5000: made to fail\" >&2\nexit 1\n");
    std::filesystem::permissions(script, std::filesystem::perms::owner_all);
    return "--hlsl-compiler '" + script.string() + "'";
  }
};

TEST_F(BuildOptions, JobsDefaultToTheNumberOfCores) {
  const CliRun run = build("-v");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // "compiling N shaders for 3 variants on T threads": T is the cores, at
  // most one thread per shader.
  std::smatch match;
  ASSERT_TRUE(std::regex_search(run.err, match,
                                std::regex("compiling ([0-9]+) shaders .* on ([0-9]+) threads")))
      << run.err;
  const int shaders = std::stoi(match[1]);
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  EXPECT_EQ(std::stoi(match[2]), std::min(cores, shaders));

  const CliRun help = run_penumbra("build --help");
  EXPECT_THAT(help.out, HasSubstr("default: the number of cores"));
}

TEST_F(BuildOptions, JobsZeroIsBadUsage) {
  const CliRun run = build("-j 0");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("--jobs"));
  EXPECT_FALSE(std::filesystem::exists(out()));
}

TEST_F(BuildOptions, QuietPrintsNoSummaryButKeepsWarnings) {
  const CliRun normal = build("");
  ASSERT_EQ(normal.exit_code, 0) << normal.err;
  EXPECT_THAT(normal.out, HasSubstr("built 3 variants"));

  const CliRun quiet = build("-q");
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.out, "");
  // Without an HLSL compiler the missing bytecode is still said.
  EXPECT_THAT(quiet.err, HasSubstr("no Direct3D bytecode made"));
  EXPECT_TRUE(std::filesystem::exists(out() / "index.json"));
}

// --profile: a row per stage that ran, each with the shaders it ran on, then
// the index's, whose runs are the variant records; even with -q. A module
// (compile, validate, optimize, interface) is made once for the targets whose text is
// the same: here spirv's and hlsl_dx10's shared vertex stages, for one.
TEST_F(BuildOptions, ProfileSaysWhereTheTimeWent) {
  const CliRun run = build("-q --profile --no-cache");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("profile: "));
  const auto runs_of = [&](const std::string& stage) {
    std::smatch match;
    const std::regex row("\n" + stage + " +[0-9.]+ +[0-9.]+% +([0-9]+) ");
    return std::regex_search(run.out, match, row) ? std::stoi(match[1]) : -1;
  };
  const int shaders = runs_of("preprocess");
  EXPECT_GT(shaders, 0) << run.out;
  for (const char* stage : {"banner", "cross-compile", "reflect", "write"}) {
    EXPECT_EQ(runs_of(stage), shaders) << stage << "\n" << run.out;
  }
  const int modules = runs_of("compile");
  EXPECT_GT(runs_of("shared-module"), 0) << run.out;
  EXPECT_EQ(modules + runs_of("shared-module"), shaders) << run.out;
  for (const char* stage : {"validate", "optimize", "interface"}) {
    EXPECT_EQ(runs_of(stage), modules) << stage << "\n" << run.out;
  }
  EXPECT_EQ(runs_of("index"), 3) << run.out;  // the manifest's three variants
  EXPECT_EQ(runs_of("cache"), -1) << "--no-cache: no cache row\n" << run.out;
}

// The jobs that share a module run on one thread, one after another, so
// that more threads never make a module twice: as many modules at -j 4 as
// at -j 1, and the same files.
TEST_F(BuildOptions, ThreadsMakeEachModuleOnce) {
  const auto modules_at = [&](int jobs) {
    const CliRun run = build("-q --profile --no-cache -j " + std::to_string(jobs));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    std::smatch match;
    const bool found =
        std::regex_search(run.out, match, std::regex("\ncompile +[0-9.]+ +[0-9.]+% +([0-9]+) "));
    EXPECT_TRUE(found) << run.out;
    return found ? std::stoi(match[1]) : -1;
  };
  const int one = modules_at(1);
  const std::string index = read_file(out() / "index.json").value();
  EXPECT_EQ(modules_at(4), one);
  EXPECT_EQ(read_file(out() / "index.json").value(), index);
}

TEST_F(BuildOptions, QuietAndVerboseExcludeEachOther) {
  const CliRun run = build("-q -v");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(out()));
}

TEST_F(BuildOptions, WithoutKeepGoingTheFirstFailureStopsTheBuild) {
  const CliRun run = build("-j 1 " + failing_compiler());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("made to fail"));
  EXPECT_FALSE(std::filesystem::exists(out()));
}

TEST_F(BuildOptions, KeepGoingReportsEveryFailingVariantAndWritesNothing) {
  // A previous library stays as it was.
  ASSERT_EQ(build("-q").exit_code, 0);
  const auto index_before = std::filesystem::last_write_time(out() / "index.json");

  const CliRun run = build("--keep-going " + failing_compiler());
  EXPECT_EQ(run.exit_code, 2);
  for (const char* variant : {"hard", "pcf_grid_k3", "pcf_grid_k5"}) {
    EXPECT_THAT(run.err, HasSubstr("variant " + std::string(variant) + ", target hlsl_dx10"))
        << "every failing variant is reported";
  }
  EXPECT_THAT(run.err, HasSubstr("shaders failed"));
  EXPECT_THAT(run.out, Not(HasSubstr("built")));
  EXPECT_EQ(std::filesystem::last_write_time(out() / "index.json"), index_before);
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    const std::string name = entry.path().filename().string();
    // home/ holds the shader cache (HOME points there).
    EXPECT_TRUE(name == "manifest.json" || name == "failing-compiler.sh" || name == "out" ||
                name == "home")
        << name << ": no staging folder left behind";
  }
}

TEST_F(BuildOptions, VariantAndTargetFilters) {
  const CliRun run = build("--variant pcf_grid_k5 --variant hard --target spirv");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("built 2 variants"));
  auto names = built_variants();
  std::ranges::sort(names);
  EXPECT_EQ(names, (std::vector<std::string>{"hard", "pcf_grid_k5"}));
  EXPECT_TRUE(std::filesystem::exists(out() / "spirv"));
  EXPECT_FALSE(std::filesystem::exists(out() / "hlsl_dx10"));
  // A build for spirv alone needs no HLSL compiler and says nothing of it.
  EXPECT_THAT(run.err, Not(HasSubstr("no Direct3D bytecode made")));
}

// The forms each variant of out/index.json lists.
std::map<std::string, std::vector<std::string>> built_forms(const std::filesystem::path& out) {
  std::ifstream in(out / "index.json");
  const auto index = nlohmann::json::parse(in);
  std::map<std::string, std::vector<std::string>> forms;
  for (const auto& variant : index.at("variants")) {
    forms[variant.at("name")] = variant.at("forms").get<std::vector<std::string>>();
  }
  return forms;
}

// The shader files under `dir`, relative to it, sorted.
std::vector<std::string> files_under(const std::filesystem::path& dir) {
  std::vector<std::string> out;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().filename() != "index.json") {
      out.push_back(std::filesystem::relative(entry.path(), dir).generic_string());
    }
  }
  std::ranges::sort(out);
  return out;
}

TEST_F(BuildOptions, EveryVariantIsBuiltInEveryFormByDefault) {
  const CliRun run = build("--target hlsl_dx10");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::vector<std::string> all = {"query", "deferred", "function"};
  for (const auto& [name, forms] : built_forms(out())) EXPECT_EQ(forms, all) << name;
  EXPECT_TRUE(std::filesystem::exists(out() / "hlsl_dx10/hard/query.frag.hlsl"));
}

// --form function builds the function form and the depth pass it reads, and
// nothing else; index.json lists only that.
TEST_F(BuildOptions, FormFilterBuildsOnlyThatFormAndWhatItReads) {
  const CliRun run = build("--form function --target hlsl_dx10 --variant hard");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(built_forms(out()),
            (std::map<std::string, std::vector<std::string>>{{"hard", {"function"}}}));
  EXPECT_EQ(files_under(out()),
            (std::vector<std::string>{"hlsl_dx10/common/depth.frag.hlsl",
                                      "hlsl_dx10/common/depth.vert.hlsl",
                                      "hlsl_dx10/hard/penumbra_visibility.hlsl"}));
  std::ifstream in(out() / "index.json");
  const auto index = nlohmann::json::parse(in);
  const auto& passes = index.at("variants").at(0).at("passes");
  EXPECT_TRUE(passes.contains("depth"));
  EXPECT_FALSE(passes.contains("query"));
  EXPECT_FALSE(passes.contains("deferred"));
}

TEST_F(BuildOptions, AnUnknownFormIsBadInputListingTheAllowedForms) {
  const CliRun run = build("--form shadow");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err,
              HasSubstr("--form shadow: unknown form; allowed: query, deferred, function"));
  EXPECT_FALSE(std::filesystem::exists(out()));
}

TEST_F(BuildOptions, AnUnknownVariantIsBadInputListingTheAllowedNames) {
  const CliRun run = build("--variant pcf_grid_k7");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("--variant pcf_grid_k7"));
  EXPECT_THAT(run.err, HasSubstr("pcf_grid_k3, pcf_grid_k5"));
  EXPECT_FALSE(std::filesystem::exists(out()));
}

TEST_F(BuildOptions, AnUnknownTargetIsBadInputListingTheAllowedTargets) {
  const CliRun run = build("--target metal");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("--target metal"));
  EXPECT_THAT(run.err, HasSubstr("hlsl_dx9"));
  EXPECT_FALSE(std::filesystem::exists(out()));
}

TEST_F(BuildOptions, ATargetTheManifestDoesNotBuildIsBadInput) {
  const CliRun run = build("--target glsl450");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("--target glsl450"));
  EXPECT_FALSE(std::filesystem::exists(out()));
}

}  // namespace
}  // namespace penumbra::testing
