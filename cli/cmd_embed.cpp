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
    std::size_t part = 0;
    std::size_t parts = 0;
    bool quiet = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "embed",
      "Write a built library as C++ sources: <name>/shaders.hpp and <name>_shaders.cpp; with "
      "--part I only <name>_shaders_I.cpp, and with --parts N (no library) the header and the "
      "<name>_shaders.cpp that joins parts 1..N");
  cmd->add_option("library", args->library, "Built library directory (holds index.json)");
  cmd->add_option("-o,--out", args->out, "Output directory")->required();
  cmd->add_option("--name", args->name, "C++ namespace and header folder of the sources")
      ->required();
  cmd->add_option("--part", args->part, "Write the library as part I of a split one")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--parts", args->parts, "Write the header and the index of N parts")
      ->check(CLI::Range(1, 4096));
  cmd->add_flag("-q,--quiet", args->quiet, "Print only errors (no summary line)");
  cmd->callback([args, &exit_code] {
    if (args->parts != 0) {
      if (!args->library.empty() || args->part != 0) {
        exit_code = report(make_error(Error::Kind::bad_input, "--parts",
                                      "takes no library and no --part: it writes the index of "
                                      "the parts that `embed LIBRARY --part I` wrote"));
        return;
      }
      if (auto written = embed_part_index(args->out, args->name, args->parts); !written) {
        exit_code = report(written.error());
      }
      return;
    }
    if (args->library.empty()) {
      exit_code = report(make_error(Error::Kind::bad_input, "library",
                                    "a built library directory is required (or --parts N)"));
      return;
    }
    auto library = load_library(args->library);
    if (!library) {
      exit_code = report(library.error());
      return;
    }
    auto summary = embed_library(*library, args->out, {.name = args->name, .part = args->part});
    if (!summary) {
      exit_code = report(summary.error());
      return;
    }
    if (args->quiet) return;
    std::cout << "embedded " << summary->programs << " programs and " << summary->functions
              << " function forms (" << summary->blob_bytes
              << " bytes of distinct code and reflection, from " << summary->source_bytes
              << " bytes of files) into " << args->out << "\n";
  });
}

}  // namespace penumbra::cli
