// penumbra: build, list and verify soft-shadow shader libraries.
#include <CLI/CLI.hpp>
#include <iostream>
#include <new>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/support/text.hpp"
#include "validators.hpp"

namespace {

// "list permutations/x.json": the command that ran and its positional
// arguments (its input files), for a message about the run as a whole.
std::string running(const CLI::App& app) {
  std::string out;
  for (const CLI::App* command : app.get_subcommands()) {
    out += command->get_name();
    for (const CLI::Option* option : command->get_options()) {
      if (!option->get_positional()) continue;
      for (const std::string& value : option->results()) out += " " + value;
    }
  }
  return penumbra::shorten(out, 200);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"penumbra: soft-shadow shader libraries for every graphics API"};
  app.set_version_flag("--version", "penumbra " + std::string(penumbra::penumbra_version()));
  app.require_subcommand(1);
  int exit_code = penumbra::cli::kExitOk;
  penumbra::cli::add_build_command(app, exit_code);
  penumbra::cli::add_list_command(app, exit_code);
  penumbra::cli::add_disk_command(app, exit_code);
  penumbra::cli::add_embed_command(app, exit_code);
  penumbra::cli::add_merge_command(app, exit_code);
  penumbra::cli::add_junit_merge_command(app, exit_code);
#ifdef PENUMBRA_HAS_VERIFY
  penumbra::cli::add_eval_command(app, exit_code);
  penumbra::cli::add_verify_command(app, exit_code);
  penumbra::cli::add_report_command(app, exit_code);
#endif
  penumbra::cli::refuse_empty_values(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Help and version are successes; every other parse error is bad usage,
    // one line like every other error (CLI11 names the argument).
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "penumbra: error: " << penumbra::shorten(e.what(), 400) << "\n";
    return penumbra::cli::kExitBadInput;
  } catch (const std::bad_alloc&) {
    return penumbra::cli::report(
        penumbra::make_error(penumbra::Error::Kind::io, running(app),
                             "out of memory; the input is too large for this machine's memory"));
  } catch (const std::exception& e) {
    // Libraries report errors as values; anything thrown below them (a
    // filesystem race) still ends with a message, not an abort.
    return penumbra::cli::report(
        penumbra::make_error(penumbra::Error::Kind::internal, running(app), e.what()));
  }
  return exit_code;
}
