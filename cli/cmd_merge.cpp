#include <iostream>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "penumbra/compiler/build.hpp"

namespace penumbra::cli {

void add_merge_command(CLI::App& app, int& exit_code) {
  struct Args {
    std::vector<std::string> parts;
    std::string out;
    bool quiet = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "merge", "Join the parts of a split build (penumbra build --group I/N) into one library");
  cmd->add_option("parts", args->parts, "Part libraries (each holds index.json)")->required();
  cmd->add_option("-o,--out", args->out, "Output directory (replaced only on success)")->required();
  cmd->add_flag("-q,--quiet", args->quiet, "Print only errors (no summary line)");
  cmd->callback([args, &exit_code] {
    if (Status usable = check_output_directory(args->out); !usable) {
      Error error = usable.error();
      error.where = "-o " + error.where;
      exit_code = report(error);
      return;
    }
    const std::vector<std::filesystem::path> parts(args->parts.begin(), args->parts.end());
    auto summary = merge_libraries(parts, args->out);
    if (!summary) {
      exit_code = report(summary.error());
      return;
    }
    if (!args->quiet) {
      std::cout << "merged " << parts.size() << " parts: " << summary->variants << " variants ("
                << summary->files << " shader files, " << summary->bytecode
                << " bytecode files) into " << args->out << "\n";
    }
  });
}

}  // namespace penumbra::cli
