// `penumbra build --shaderlib DIR` and `--depfile FILE`, run on the real
// executable: the folder gives the same library as the embedded copy, the
// depfile lists the files the built variants include, and a shader error
// points into the folder's file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_harness.hpp"

namespace penumbra::testing {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

// pcss (with its filter and disks), pcf_poisson and hard, for text targets.
constexpr const char* kManifest =
    R"({"schema": 1, "targets": ["spirv", "glsl450", "hlsl_dx10", "essl300"],)"
    R"( "sets": [{"technique": "hard"},)"
    R"( {"technique": "pcf_poisson", "pcf_samples": 16, "disk": "whitepaper16"},)"
    R"( {"technique": "pcss", "blocker_samples": 16, "pcf_samples": 16,)"
    R"(  "disk": "whitepaper16"}]})";

constexpr const char* kPcssOnly =
    R"({"schema": 1, "targets": ["spirv"], "sets": [{"technique": "pcss",)"
    R"( "blocker_samples": 16, "pcf_samples": 16, "disk": "whitepaper16"}]})";

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string quoted(const fs::path& path) {
  return "'" + path.string() + "'";
}

class Shaderlib : public ::testing::Test {
 protected:
  ScratchDir dir{"shaderlib"};

  CliRun build(const std::string& manifest, const fs::path& out, const std::string& flags) {
    const auto file = dir.write("manifest.json", manifest);
    const std::string home = (dir.path() / "home").string();
    return run_penumbra(
        "build " + quoted(file) + " -o " + quoted(out) + " -q " + flags,
        "HOME='" + home + "' XDG_CACHE_HOME='" + home + "/cache' " + "PENUMBRA_HLSL_COMPILER=");
  }
};

TEST_F(Shaderlib, FolderBuildsTheSameLibraryAsTheEmbeddedCopy) {
  const fs::path embedded = dir.path() / "embedded";
  const fs::path folder = dir.path() / "folder";
  const CliRun a = build(kManifest, embedded, "");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const CliRun b = build(kManifest, folder, "--shaderlib " + quoted(PENUMBRA_SOURCE_SHADERLIB));
  ASSERT_EQ(b.exit_code, 0) << b.err;

  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(embedded)) {
    if (entry.is_regular_file()) files.push_back(fs::relative(entry.path(), embedded));
  }
  std::size_t in_folder = 0;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file()) ++in_folder;
  }
  ASSERT_GT(files.size(), 10u);
  EXPECT_EQ(files.size(), in_folder);
  for (const fs::path& file : files) {  // index.json too, generator field and all
    EXPECT_EQ(read_text(embedded / file), read_text(folder / file)) << file;
  }
}

TEST_F(Shaderlib, MissingOrForeignFolderIsBadInput) {
  const fs::path out = dir.path() / "out";
  const CliRun missing = build(kPcssOnly, out, "--shaderlib " + quoted(dir.path() / "nowhere"));
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_THAT(missing.err, HasSubstr("--shaderlib"));
  EXPECT_THAT(missing.err, HasSubstr("is not a directory"));

  fs::create_directories(dir.path() / "empty" / "passes");
  const CliRun foreign = build(kPcssOnly, out, "--shaderlib " + quoted(dir.path() / "empty"));
  EXPECT_EQ(foreign.exit_code, 2);
  EXPECT_THAT(foreign.err, HasSubstr("--shaderlib"));
  EXPECT_THAT(foreign.err, HasSubstr("passes/query.frag"));
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(Shaderlib, DepfileListsTheIncludedFolderFiles) {
  const fs::path out = dir.path() / "out";
  const fs::path depfile = dir.path() / "lib.d";
  const CliRun run =
      build(kPcssOnly, out,
            "--shaderlib " + quoted(PENUMBRA_SOURCE_SHADERLIB) + " --depfile " + quoted(depfile));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string text = read_text(depfile);
  const std::string shaderlib = fs::path(PENUMBRA_SOURCE_SHADERLIB).lexically_normal().string();
  EXPECT_EQ(text.rfind((out / "index.json").string() + ": ", 0), 0u) << text;
  EXPECT_THAT(text, HasSubstr((dir.path() / "manifest.json").string()));
  EXPECT_THAT(text, HasSubstr(shaderlib + "/passes/query.frag"));
  EXPECT_THAT(text, HasSubstr(shaderlib + "/passes/depth.vert"));
  EXPECT_THAT(text, HasSubstr(shaderlib + "/techniques/pcss.glsl"));
  EXPECT_THAT(text, HasSubstr(shaderlib + "/techniques/pcss_filter.glsl"));
  EXPECT_THAT(text, HasSubstr(shaderlib + "/common/disks.glsl"));
  EXPECT_THAT(text, Not(HasSubstr("techniques/hard.glsl")));
  EXPECT_THAT(text, Not(HasSubstr("techniques/pcf_poisson.glsl")));
  EXPECT_THAT(text, Not(HasSubstr("minmax")));
}

TEST_F(Shaderlib, DepfileOfTheEmbeddedCopyListsTheManifestAlone) {
  const fs::path out = dir.path() / "out";
  const fs::path depfile = dir.path() / "lib.d";
  const CliRun run = build(kPcssOnly, out, "--depfile " + quoted(depfile));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(read_text(depfile),
            (out / "index.json").string() + ": " + (dir.path() / "manifest.json").string() + "\n");
}

// A copy of the shader library whose techniques/pcss.glsl has `line` in
// place of its line 7 (a blank one).
fs::path copy_with_line_7(const fs::path& dir, const std::string& line) {
  const fs::path copy = dir / "copy";
  fs::copy(PENUMBRA_SOURCE_SHADERLIB, copy, fs::copy_options::recursive);
  const fs::path pcss = copy / "techniques" / "pcss.glsl";
  std::istringstream lines(read_text(pcss));
  std::string text;
  int number = 0;
  for (std::string original; std::getline(lines, original);) {
    text += (++number == 7 ? line : original) + "\n";
  }
  std::ofstream(pcss, std::ios::binary) << text;
  return copy;
}

TEST_F(Shaderlib, CompileErrorPointsIntoTheFolderFile) {
  const fs::path out = dir.path() / "out";
  const fs::path depfile = dir.path() / "lib.d";
  ASSERT_EQ(build(kPcssOnly, out, "").exit_code, 0);
  const std::string index = read_text(out / "index.json");

  // glslang names no token for a syntax error, only the grammar's: the
  // column is the semicolon's.
  const fs::path copy = copy_with_line_7(dir.path(), "float broken = ;");
  const CliRun run =
      build(kPcssOnly, out, "--shaderlib " + quoted(copy) + " --depfile " + quoted(depfile));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr((copy / "techniques" / "pcss.glsl").string() + ":7:16: error: "));
  EXPECT_THAT(run.err, HasSubstr("syntax error"));
  EXPECT_EQ(read_text(out / "index.json"), index);  // OUT untouched
  EXPECT_FALSE(fs::exists(depfile));
}

TEST_F(Shaderlib, CompileErrorColumnIsTheNamedToken) {
  const fs::path copy = copy_with_line_7(dir.path(), "const float broken = 2.0 * missing_name;");
  const CliRun run = build(kPcssOnly, dir.path() / "out", "--shaderlib " + quoted(copy));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr((copy / "techniques" / "pcss.glsl").string() + ":7:28: error: "));
  EXPECT_THAT(run.err, HasSubstr("missing_name"));
}

}  // namespace
}  // namespace penumbra::testing
