// penumbra: build, list and verify soft-shadow shader libraries.
#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "penumbra/compiler/build.hpp"

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
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Help and version are successes; every other parse error is bad usage.
    const int code = app.exit(e);
    return code == 0 ? 0 : penumbra::cli::kExitBadInput;
  } catch (const std::exception& e) {
    // Libraries report errors as values; anything thrown below them (out of
    // memory, a filesystem race) still ends with a message, not an abort.
    return penumbra::cli::report(
        penumbra::make_error(penumbra::Error::Kind::internal, "", e.what()));
  }
  return exit_code;
}
