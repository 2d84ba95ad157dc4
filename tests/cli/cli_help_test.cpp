// Every choice `--help` shows is accepted: walks the subcommands listed by
// `penumbra --help` and runs each with every value of each option whose
// help lists its allowed values ("--method TEXT:{a,b,c}").
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <sstream>

#include "cli_harness.hpp"

namespace penumbra::testing {
namespace {

using ::testing::HasSubstr;

// The subcommands listed by `penumbra --help`.
std::vector<std::string> subcommands() {
  const CliRun run = run_penumbra("--help");
  EXPECT_EQ(run.exit_code, 0);
  std::vector<std::string> names;
  std::istringstream lines(run.out);
  std::string line;
  bool in_list = false;
  static const std::regex kEntry(R"(^\s+([a-z][a-z0-9_-]*)\s{2,}.*$)");
  while (std::getline(lines, line)) {
    if (line.starts_with("Subcommands:")) {
      in_list = true;
      continue;
    }
    std::smatch match;
    if (in_list && std::regex_match(line, match, kEntry)) names.push_back(match[1]);
  }
  return names;
}

// Option name -> its allowed values, from `penumbra SUB --help`.
std::map<std::string, std::vector<std::string>> choices(const std::string& subcommand) {
  const CliRun run = run_penumbra(subcommand + " --help");
  EXPECT_EQ(run.exit_code, 0) << subcommand;
  static const std::regex kChoice(R"((--[a-z0-9-]+) [A-Z]+:\{([^}]*)\})");
  std::map<std::string, std::vector<std::string>> out;
  for (auto it = std::sregex_iterator(run.out.begin(), run.out.end(), kChoice);
       it != std::sregex_iterator(); ++it) {
    std::istringstream values((*it)[2].str());
    std::string value;
    while (std::getline(values, value, ',')) out[(*it)[1]].push_back(value);
  }
  return out;
}

TEST(CliHelp, EveryListedChoiceIsAccepted) {
  ScratchDir dir("cli-help");
  const auto manifest = dir.write(
      "manifest.json", R"({"schema": 1, "targets": ["spirv"], "sets": [{"technique": ["hard"]}]})");
  // A quick, successful run of each subcommand that has choices, which a choice is appended to.
  const std::map<std::string, std::string> base = {
      {"disk", "disk --count 16"},
      {"build", "build '" + manifest.string() + "' -q -o '" + (dir.path() / "out").string() + "'"},
      {"list", "list '" + manifest.string() + "'"},
  };
  const std::vector<std::string> names = subcommands();
  EXPECT_THAT(names, ::testing::IsSupersetOf({"build", "list", "disk"}));
  std::size_t checked = 0;
  for (const std::string& name : names) {
    for (const auto& [option, values] : choices(name)) {
      const auto run_of = base.find(name);
      if (run_of == base.end()) {
        ADD_FAILURE() << name << " " << option << " lists choices; give the test a base run of "
                      << name;
        continue;
      }
      for (const std::string& value : values) {
        const CliRun run = run_penumbra(run_of->second + " " + option + " " + value);
        EXPECT_EQ(run.exit_code, 0) << name << " " << option << " " << value << ": " << run.err;
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 3u) << "disk --method's choices were not found in its help";
}

TEST(CliHelp, DiskWhitepaperNeedsNoCount) {
  const CliRun run = run_penumbra("disk --method whitepaper");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("\"whitepaper16\""));
}

TEST(CliHelp, DiskWhitepaperWithAnotherCountIsBadInput) {
  const CliRun run = run_penumbra("disk --method whitepaper --count 8");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("--count 8"));
  EXPECT_THAT(run.err, HasSubstr("16"));
  EXPECT_TRUE(run.out.empty());
}

TEST(CliHelp, DiskUnknownMethodListsTheAllowedOnes) {
  const CliRun run = run_penumbra("disk --count 16 --method halton");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("--method"));
  EXPECT_THAT(run.err, HasSubstr("whitepaper"));
}

}  // namespace
}  // namespace penumbra::testing
