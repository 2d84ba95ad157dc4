#include <iostream>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "junit.hpp"
#include "output_file.hpp"
#include "penumbra/support/atomic_file.hpp"
#include "penumbra/support/file.hpp"

namespace penumbra::cli {

void add_junit_merge_command(CLI::App& app, int& exit_code) {
  struct Args {
    std::vector<std::string> reports;
    std::string out;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "junit-merge",
      "Merge the JUnit reports of every shard of `penumbra verify --shard` into one");
  cmd->add_option("reports", args->reports, "Each shard's `penumbra verify --junit` report")
      ->required();
  cmd->add_option("-o,--out", args->out, "The merged JUnit report")->required();
  cmd->callback([args, &exit_code] {
    if (Status s = check_output_file(args->out, "-o"); !s) {
      exit_code = report(s.error());
      return;
    }
    std::vector<std::pair<std::string, JunitReport>> shards;
    for (const std::string& file : args->reports) {
      auto text = read_file(file);
      if (!text) {
        exit_code = report(make_error(
            Error::Kind::io, file,
            text.error().message + "; allowed: each shard's penumbra verify --junit report"));
        return;
      }
      auto parsed = parse_junit_xml(*text, file);
      if (!parsed) {
        exit_code = report(parsed.error());
        return;
      }
      shards.emplace_back(file, std::move(*parsed));
    }
    auto merged = merge_junit_shards(shards);
    if (!merged) {
      exit_code = report(merged.error());
      return;
    }
    if (Status s = write_file_atomic(args->out, to_junit_xml(*merged)); !s) {
      exit_code = report(s.error());
      return;
    }
    std::size_t passed = 0;
    std::size_t failed = 0;
    std::size_t skipped = 0;
    for (const JunitSuite& suite : merged->suites) {
      for (const JunitCase& c : suite.cases) {
        passed += c.outcome == JunitCase::Outcome::passed ? 1 : 0;
        skipped += c.outcome == JunitCase::Outcome::skipped ? 1 : 0;
        if (c.outcome != JunitCase::Outcome::failed) continue;
        ++failed;
        std::cout << "FAIL " << c.classname << " " << c.name << ": " << c.message << "\n";
      }
    }
    std::cout << passed << " passed, " << failed << " failed, " << skipped << " skipped, from "
              << shards.size() << " shards\nresults: " << args->out << "\n";
    exit_code = merged->failed() ? kExitCheckFailed : kExitOk;
  });
}

}  // namespace penumbra::cli
