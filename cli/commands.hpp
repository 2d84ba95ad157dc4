// The subcommands of `penumbra`. Each registers itself on the app and sets
// the process exit code when it runs.
#pragma once

#include <CLI/CLI.hpp>

namespace penumbra::cli {

void add_build_command(CLI::App& app, int& exit_code);
void add_list_command(CLI::App& app, int& exit_code);
void add_disk_command(CLI::App& app, int& exit_code);
void add_embed_command(CLI::App& app, int& exit_code);
void add_merge_command(CLI::App& app, int& exit_code);
void add_junit_merge_command(CLI::App& app, int& exit_code);
#ifdef PENUMBRA_HAS_VERIFY
void add_eval_command(CLI::App& app, int& exit_code);
void add_verify_command(CLI::App& app, int& exit_code);
void add_report_command(CLI::App& app, int& exit_code);
#endif

}  // namespace penumbra::cli
