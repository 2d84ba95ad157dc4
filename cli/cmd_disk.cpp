#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "penumbra/compiler/disk.hpp"
#include "penumbra/library/disk_json.hpp"
#include "validators.hpp"

namespace penumbra::cli {
namespace {

constexpr const char* kWhitepaper = "whitepaper";  // the built-in 16 points, not generated

}  // namespace

void add_disk_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<DiskOptions>();
  CLI::App* cmd = app.add_subcommand("disk", "Print a Poisson disk as JSON");
  cmd->add_option("--count", options->count, "Number of points (1..128; whitepaper: 16)")
      ->capture_default_str();
  cmd->add_option("--seed", options->seed, "Generator seed (0..2^64-1)")
      ->capture_default_str()
      ->check(seed_value());
  cmd->add_option("--method", options->method,
                  "Generator, or whitepaper for the NVIDIA PCSS whitepaper's 16 points")
      ->capture_default_str()
      ->check(CLI::IsMember(
          {"sample_elimination", "best_candidate", "square_stratified", "square_r2", kWhitepaper}));
  cmd->callback([options, &exit_code] {
    if (options->method == kWhitepaper && options->count != 16) {
      exit_code =
          report(make_error(Error::Kind::bad_input, "--count " + std::to_string(options->count),
                            "the whitepaper disk has exactly 16 points; give --count 16 "
                            "or leave --count out"));
      return;
    }
    auto disk =
        options->method == kWhitepaper ? Result<Disk>(whitepaper16()) : generate_disk(*options);
    if (!disk) {
      // generate_disk knows no argument names; its one check is the count.
      Error error = disk.error();
      if (error.where.empty()) error.where = "--count " + std::to_string(options->count);
      exit_code = report(error);
      return;
    }
    std::cout << disk_to_json(*disk).dump(2) << "\n";
  });
}

}  // namespace penumbra::cli
