#include <iostream>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "penumbra/compiler/embed.hpp"

namespace penumbra::cli {

void add_embed_command(CLI::App& app, int& exit_code) {
  struct Args {
    std::string library;
    std::string out;
    std::string name;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "embed", "Write a built library as C++ sources: <name>/shaders.hpp and <name>_shaders.cpp");
  cmd->add_option("library", args->library, "Built library directory (holds index.json)")
      ->required();
  cmd->add_option("-o,--out", args->out, "Output directory")->required();
  cmd->add_option("--name", args->name, "C++ namespace and header folder of the sources")
      ->required();
  cmd->callback([args, &exit_code] {
    auto library = load_library(args->library);
    if (!library) {
      exit_code = report(library.error());
      return;
    }
    auto summary = embed_library(*library, args->out, {.name = args->name});
    if (!summary) {
      exit_code = report(summary.error());
      return;
    }
    std::cout << "embedded " << summary->programs << " programs (" << summary->blob_bytes
              << " bytes of distinct code and reflection, from " << summary->source_bytes
              << " bytes of files) into " << args->out << "\n";
  });
}

}  // namespace penumbra::cli
