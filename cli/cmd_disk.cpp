#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "penumbra/compiler/disk.hpp"

namespace penumbra::cli {

void add_disk_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<DiskOptions>();
  CLI::App* cmd = app.add_subcommand("disk", "Print a Poisson disk as JSON");
  cmd->add_option("--count", options->count, "Number of points (1..128)")->required();
  cmd->add_option("--seed", options->seed, "Generator seed");
  cmd->add_option("--method", options->method,
                  "Generator: sample_elimination, best_candidate, or whitepaper (16 points)");
  cmd->callback([options, &exit_code] {
    auto disk = options->method == "whitepaper" && options->count == 16
                    ? Result<Disk>(whitepaper16())
                    : generate_disk(*options);
    if (!disk) {
      exit_code = report(disk.error());
      return;
    }
    std::cout << disk_to_json(*disk).dump(2) << "\n";
  });
}

}  // namespace penumbra::cli
