#include <iostream>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/manifest.hpp"

namespace penumbra::cli {

void add_build_command(CLI::App& app, int& exit_code) {
  struct Args {
    std::string manifest;
    std::string out;
    int jobs = 1;
    bool verbose = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("build", "Compile every variant of a manifest into OUT");
  cmd->add_option("manifest", args->manifest, "Permutation manifest (JSON)")->required();
  cmd->add_option("-o,--out", args->out, "Output directory (replaced only on success)")->required();
  cmd->add_option("-j,--jobs", args->jobs, "Shaders compiled in parallel")
      ->check(CLI::Range(1, 64));
  cmd->add_flag("-v,--verbose", args->verbose, "Print progress notes");
  cmd->callback([args, &exit_code] {
    auto variants = load_variants(args->manifest);
    if (!variants) {
      exit_code = report(variants.error());
      return;
    }
    auto summary = build_library(*variants, args->out, BuildOptions{.jobs = args->jobs},
                                 stderr_diagnostics(args->verbose));
    if (!summary) {
      exit_code = report(summary.error());
      return;
    }
    std::cout << "built " << summary->variants << " variants (" << summary->files
              << " shader files) into " << args->out << "\n";
  });
}

}  // namespace penumbra::cli
