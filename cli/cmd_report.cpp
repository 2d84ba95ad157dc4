#include <iostream>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "hlsl_compiler.hpp"
#include "jobs.hpp"
#include "output_file.hpp"
#include "path_flags.hpp"
#include "penumbra/report/report.hpp"
#include "penumbra/support/atomic_file.hpp"
#include "validators.hpp"

namespace penumbra::cli {
namespace {

namespace fs = std::filesystem;

struct ReportArgs {
  std::string library;
  std::string output;  // empty: LIBRARY/report
  std::string device;
  std::vector<std::string> variants;
  std::vector<std::string> targets;
  std::string hlsl_compiler;
  std::vector<std::string> skipped;  // from the skip flags (--no-gl, --no-wine)
  bool validation = false;
  bool verbose = false;
  bool quiet = false;  // no progress
  int jobs = 0;        // 0: every core
};

// DIR is staged beside itself and renamed, its missing parents made: the
// nearest existing one must take new files. Checked before any picture is
// drawn; a library's own report folder names the way out.
Status check_report_parent(const fs::path& out, bool in_library) {
  fs::path parent = fs::absolute(out).parent_path();
  std::error_code ec;
  while (!fs::exists(parent, ec) && parent != parent.parent_path()) parent = parent.parent_path();
  const std::string why = why_unwritable(parent);
  if (why.empty()) return {};
  return make_error(Error::Kind::bad_input, in_library ? out.string() : "-o " + out.string(),
                    "cannot write into " + parent.string() + " (" + why +
                        "); allowed: a directory whose parent penumbra may write to" +
                        (in_library ? "; pass -o DIR to write the report elsewhere" : ""));
}

Status run_report(const ReportArgs& args) {
  PENUMBRA_TRY_ASSIGN(const fs::path compiler, find_hlsl_compiler(args.hlsl_compiler));
  PENUMBRA_TRY_ASSIGN(const Library library, load_library(args.library));
  const fs::path out = args.output.empty() ? library.root / "report" : fs::path(args.output);
  ReportOptions options;
  options.pictures.variants = args.variants;
  options.pictures.skipped = args.skipped;
  options.pictures.bytecode = {.compiler = compiler};
  options.pictures.jobs = args.jobs;
  options.pictures.progress = stderr_progress(args.quiet);
  options.final_dir = out;
  for (const std::string& name : args.targets) {
    auto target = parse_target(name);
    if (!target) {
      return make_error(Error::Kind::bad_input, "--target " + name,
                        "unknown target; allowed: " + allowed_targets());
    }
    options.pictures.targets.push_back(*target);
  }
  for (const std::string& name : args.variants) {
    if (!library.find(name)) {
      return make_error(Error::Kind::bad_input, "--variant " + name,
                        "no such variant in " + library.root.string());
    }
  }
  PENUMBRA_TRY(check_report_directory(out));
  PENUMBRA_TRY(check_report_parent(out, args.output.empty()));
  limit_software_rasterizers(args.jobs);
  keep_freed_memory();
  PENUMBRA_TRY_ASSIGN(auto engine,
                      Engine::create({.device = args.device, .validation = args.validation},
                                     stderr_diagnostics(args.verbose)));
  PENUMBRA_TRY_ASSIGN(auto staged, StagedDirectory::create(out));
  PENUMBRA_TRY(
      write_report(library, *engine, staged.staging(), options, stderr_diagnostics(args.verbose)));
  PENUMBRA_TRY(staged.commit());
  std::cout << "report: " << (out / "index.html").string() << "\n";
  return {};
}

}  // namespace

void add_report_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ReportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "report",
      "Picture every variant on a test stage, measure it against the exact area light and write "
      "an HTML report");
  cmd->add_option("library", args->library, "Built library directory")->required();
  cmd->add_option("-o,--output", args->output, "Report directory (default: LIBRARY/report)");
  cmd->add_option("--device", args->device, "Vulkan device: index or name substring");
  cmd->add_option("--variant", args->variants, "Only these variants (repeatable)");
  cmd->add_option("--target", args->targets, "Only these targets (repeatable)");
  cmd->add_option("--hlsl-compiler", args->hlsl_compiler, kHlslCompilerHelp);
  add_skip_flags(cmd, args->skipped);
  cmd->add_flag("--validation", args->validation, "Enable the Vulkan validation layer");
  cmd->add_flag("-v,--verbose", args->verbose, "Print progress notes");
  cmd->add_flag("-q,--quiet", args->quiet, "Print no progress (runs done of the total)");
  add_jobs_option(cmd, args->jobs);
  cmd->callback([args, &exit_code] {
    const Status s = run_report(*args);
    exit_code = s ? kExitOk : report(s.error());
  });
}

}  // namespace penumbra::cli
