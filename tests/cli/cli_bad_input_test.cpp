// Bad input of every kind (docs/robustness.md, "Bad input"): exit 2, one
// message naming the file, JSON path or argument and what is allowed,
// nothing written, bounded time and memory.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_harness.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

std::string quoted(const std::filesystem::path& path) {
  return "'" + path.string() + "'";
}

// Lines of stderr: bad input gets exactly one.
std::size_t lines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

class BadInput : public ::testing::Test {
 protected:
  ScratchDir dir{"bad-input"};

  // `penumbra list` on `text` written as m.json.
  CliRun list(const std::string& text, const std::string& env = "") {
    return run_penumbra("list " + quoted(dir.write("m.json", text)), env);
  }

  // Asserts one error line and exit 2; returns the line.
  static std::string one_error(const CliRun& run) {
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_EQ(lines(run.err), 1u) << run.err;
    EXPECT_EQ(run.out, "");
    return run.err;
  }
};

// 300 copies of one value on each of three axes are one value each: listing
// stays within a small address space (the product of the copies took GBs).
TEST_F(BadInput, DuplicatesOnAnAxisAreMergedFirst) {
  if (!kAddressSpaceCanBeLimited) GTEST_SKIP() << "ulimit -v cannot bound a sanitized binary";
  std::string samples;
  std::string disks;
  for (int i = 0; i < 300; ++i) {
    samples += std::string(i ? ", " : "") + "16";
    disks += std::string(i ? ", " : "") + "\"whitepaper16\"";
  }
  const CliRun run =
      list(R"({"schema": 1, "sets": [{"technique": "pcss", "disk": [)" + disks +
               R"(], "blocker_samples": [)" + samples + R"(], "pcf_samples": [)" + samples + "]}]}",
           "ulimit -v 1500000;");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "pcss_b16_p16_whitepaper16\n");
}

// 128 x 128 sample counts x 7 disks: refused before anything is made, unless
// the manifest raises its limit.
TEST_F(BadInput, TooManyVariantsAreRefused) {
  std::string disks;
  std::string names;
  for (int i = 0; i < 7; ++i) {
    disks += std::string(i ? ", " : "") + "\"d" + std::to_string(i) +
             "\": {\"seed\": " + std::to_string(i) + "}";
    names += std::string(i ? ", " : "") + "\"d" + std::to_string(i) + "\"";
  }
  std::string counts;
  for (int i = 1; i <= 128; ++i) counts += std::string(i > 1 ? ", " : "") + std::to_string(i);
  const std::string set = R"({"technique": "pcss", "blocker_samples": [)" + counts +
                          R"(], "pcf_samples": [)" + counts + R"(], "disk": [)" + names + "]}";
  const std::string err =
      one_error(list(R"({"schema": 1, "disks": {)" + disks + R"(}, "sets": [)" + set + "]}"));
  EXPECT_THAT(err, HasSubstr("m.json"));
  EXPECT_THAT(err, HasSubstr("/sets/0"));
  EXPECT_THAT(err, HasSubstr("114688 variants"));
  EXPECT_THAT(err, HasSubstr("max_variants"));

  const std::string three = R"({"technique": "pcf_grid", "kernel": [1, 3, 5]})";
  EXPECT_THAT(one_error(list(R"({"schema": 1, "max_variants": 2, "sets": [)" + three + "]}")),
              HasSubstr("allowed at most 2"));
  const CliRun raised = list(R"({"schema": 1, "max_variants": 3, "sets": [)" + three + "]}");
  EXPECT_EQ(raised.exit_code, 0) << raised.err;
  EXPECT_EQ(raised.out, "pcf_grid_k1\npcf_grid_k3\npcf_grid_k5\n");
  EXPECT_THAT(one_error(list(R"({"schema": 1, "max_variants": 0, "sets": [)" + three + "]}")),
              HasSubstr("/max_variants"));
}

// Running out of memory names the command and its input, not std::bad_alloc.
TEST_F(BadInput, OutOfMemoryNamesWhatWasBeingDone) {
  if (!kAddressSpaceCanBeLimited) GTEST_SKIP() << "ulimit -v cannot bound a sanitized binary";
  // Ten million nested arrays: a small file, a large document.
  const std::size_t depth = 10'000'000;
  const auto file = dir.path() / "deep.json";
  {
    std::ofstream out(file, std::ios::binary);
    out << std::string(depth, '[') << std::string(depth, ']');
  }
  const CliRun run = run_penumbra("list " + quoted(file), "ulimit -v 600000;");
  const std::string err = one_error(run);
  EXPECT_THAT(err, HasSubstr("out of memory"));
  EXPECT_THAT(err, HasSubstr("list"));
  EXPECT_THAT(err, HasSubstr("deep.json"));
  EXPECT_THAT(err, Not(HasSubstr("bad_alloc")));
}

// A library with one pcf_grid variant, its index.json edited by `edit`, then
// read by `penumbra embed`, which must refuse it without writing anything.
class BadIndex : public BadInput {
 protected:
  std::string embed_fails(const std::function<void(nlohmann::json&)>& edit) {
    const auto manifest = dir.write(
        "lib.json",
        R"({"schema": 1, "targets": ["spirv"], "sets": [{"technique": "pcf_grid", "kernel": 3}]})");
    const auto lib = dir.path() / "lib";
    const CliRun built =
        run_penumbra("build -q --no-cache " + quoted(manifest) + " -o " + quoted(lib));
    EXPECT_EQ(built.exit_code, 0) << built.err;
    nlohmann::json index;
    std::ifstream(lib / "index.json") >> index;
    edit(index);
    std::ofstream(lib / "index.json") << index.dump();
    const auto out = dir.path() / "embedded";
    const CliRun run = run_penumbra("embed " + quoted(lib) + " --name shaders -o " + quoted(out));
    EXPECT_FALSE(std::filesystem::exists(out));
    const std::string err = one_error(run);
    EXPECT_THAT(err, HasSubstr("index.json"));
    return err;
  }
};

TEST_F(BadIndex, CountsAreRangeChecked) {
  const std::string kernel =
      embed_fails([](nlohmann::json& j) { j["variants"][0]["keys"]["kernel"] = 100001; });
  EXPECT_THAT(kernel, HasSubstr("/variants/0/keys/kernel"));
  EXPECT_THAT(kernel, HasSubstr("100001"));
  EXPECT_THAT(kernel, HasSubstr("1..128"));
  const std::string radius =
      embed_fails([](nlohmann::json& j) { j["variants"][0]["keys"]["blur_radius"] = 1000; });
  EXPECT_THAT(radius, HasSubstr("/variants/0/keys/blur_radius"));
  EXPECT_THAT(radius, HasSubstr("1..32"));
}

TEST_F(BadIndex, TypeErrorsNameThePath) {
  const std::string name = embed_fails([](nlohmann::json& j) { j["variants"][0]["name"] = 5; });
  EXPECT_THAT(name, HasSubstr("/variants/0/name"));
  EXPECT_THAT(name, HasSubstr("expected a string, got 5"));
  EXPECT_THAT(name, Not(HasSubstr("json.exception")));
  const std::string keys =
      embed_fails([](nlohmann::json& j) { j["variants"][0]["keys"]["kernel"] = "3"; });
  EXPECT_THAT(keys, HasSubstr("/variants/0/keys/kernel"));
  EXPECT_THAT(keys, Not(HasSubstr("json.exception")));
}

// A 10 MB value is quoted by its first characters, not echoed whole.
TEST_F(BadInput, LongValuesAreShortenedInMessages) {
  const std::string huge(10'000'000, 'x');
  const std::string technique =
      one_error(list(R"({"schema": 1, "sets": [{"technique": ")" + huge + "\"}]}"));
  EXPECT_LT(technique.size(), 400u);
  EXPECT_THAT(technique, HasSubstr("/sets/0/technique"));
  EXPECT_THAT(technique, HasSubstr("…"));
  const std::string key = one_error(list(R"({"schema": 1, ")" + huge + "\": 1}"));
  EXPECT_LT(key.size(), 400u);
  const std::string malformed = one_error(list(R"({"schema": 1, "sets": ")" + huge));
  EXPECT_LT(malformed.size(), 400u);
  EXPECT_THAT(malformed, HasSubstr("malformed JSON"));
}

TEST_F(BadInput, NegativeSeedIsRefused) {
  const std::string err = one_error(run_penumbra("disk --seed -1"));
  EXPECT_THAT(err, HasSubstr("--seed"));
  EXPECT_THAT(err, HasSubstr("0..18446744073709551615"));
  EXPECT_THAT(one_error(run_penumbra("disk --count 0")), HasSubstr("--count 0: "));
}

TEST_F(BadInput, NulBytesAfterTheJsonAreRefused) {
  const std::string json = R"({"schema": 1, "sets": [{"technique": "hard"}]})";
  const std::string err = one_error(list(json + std::string(4, '\0')));
  EXPECT_THAT(err, HasSubstr("m.json:1:" + std::to_string(json.size() + 1)));
  EXPECT_THAT(err, HasSubstr("NUL"));
}

TEST_F(BadInput, ExclusionsThatRemoveEverythingAreAnError) {
  const std::string err = one_error(list(
      R"({"schema": 1, "sets": [{"technique": "hard"}], "exclude": [{"technique": "hard"}]})"));
  EXPECT_THAT(err, HasSubstr("m.json"));
  EXPECT_THAT(err, HasSubstr("/exclude"));
  EXPECT_THAT(err, HasSubstr("every variant"));
}

TEST_F(BadInput, LongDiskNamesAreRefusedUpFront) {
  const std::string name(300, 'd');
  const std::string err = one_error(
      list(R"({"schema": 1, "disks": {")" + name +
           R"(": {}}, "sets": [{"technique": "pcf_poisson", "pcf_samples": 16, "disk": ")" + name +
           "\"}]}"));
  EXPECT_THAT(err, HasSubstr("/disks/ddd"));
  EXPECT_THAT(err, HasSubstr("at most 32 characters"));
  EXPECT_LT(err.size(), 400u);
}

TEST_F(BadInput, EmptyArgumentsAndFoldersAreNamed) {
  const std::string manifest = one_error(run_penumbra("list ''"));
  EXPECT_THAT(manifest, HasSubstr("manifest"));
  EXPECT_THAT(manifest, HasSubstr("empty"));
  const std::string out =
      one_error(run_penumbra("build " + quoted(dir.write("m.json", "{}")) + " -o ''"));
  EXPECT_THAT(out, HasSubstr("--out"));
  EXPECT_THAT(out, HasSubstr("empty"));
  const std::string report = one_error(run_penumbra("junit-merge " + quoted(dir.path()) + " -o " +
                                                    quoted(dir.path() / "merged.xml")));
  EXPECT_THAT(report, HasSubstr(dir.path().string()));
  EXPECT_THAT(report, HasSubstr("Is a directory"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "merged.xml"));
}

TEST_F(BadInput, IoErrorsSayWhy) {
  const auto missing = dir.path() / "no-such-library";
  const std::string err = one_error(
      run_penumbra("embed " + quoted(missing) + " --name x -o " + quoted(dir.path() / "e")));
  EXPECT_THAT(err, HasSubstr("index.json"));
  EXPECT_THAT(err, HasSubstr("No such file or directory"));
}

}  // namespace
}  // namespace penumbra::testing
