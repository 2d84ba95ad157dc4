#include <iostream>
#include <map>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "hlsl_compiler.hpp"
#include "jobs.hpp"
#include "output_file.hpp"
#include "path_flags.hpp"
#include "penumbra/support/atomic_file.hpp"
#include "penumbra/verify/verify.hpp"
#include "verify_junit.hpp"

namespace penumbra::cli {
namespace {

struct VerifyArgs {
  std::string library;
  std::string device;
  std::vector<std::string> variants;
  std::vector<std::string> targets;
  std::string hlsl_compiler;
  std::string shard;                 // "I/N"; empty: the whole library
  std::string junit;                 // JUnit report to write; empty: none
  std::string results;               // verify.json to write; empty: LIBRARY/verify.json
  std::vector<std::string> skipped;  // from the skip flags (--no-gl, --no-wine)
  std::vector<std::string> paths;
  std::string map_format = "d32_float";
  bool validation = false;
  bool optimized_jit = false;  // let Mesa's software rasterizers optimize the shaders they compile
  bool verbose = false;
  bool quiet = false;      // only failures and the totals
  int jobs = 0;            // 0: every core
  int device_threads = 2;  // threads driving devices, each with its own
};

std::string run_label(const VariantRun& v, const TargetRun& t) {
  std::string label = v.name + " [" + std::string(to_string(t.target));
  if (t.backend != "vulkan") label += " on " + t.backend;
  return label + "]";
}

// ", perspective" after a per-target check's target where its maps are an
// engine's: each encoding has its own.
std::string encoding_note(MapEncoding encoding) {
  return encoding == MapEncoding::linear ? "" : ", " + std::string(to_string(encoding));
}

// Every check's line (with `quiet`, only the failed ones), then the totals.
void print_summary(const VerifyReport& report, bool quiet) {
  for (const DepthCheck& c : report.depth_checks) {
    if (quiet && c.pass) continue;
    std::cout << (c.pass ? "PASS " : "FAIL ") << "depth pass [" << to_string(c.target)
              << (c.backend == "vulkan" ? "" : " on " + c.backend) << encoding_note(c.map_encoding)
              << "] on " << c.scene << ": " << c.mismatched << " of " << c.texels
              << " texels off\n";
  }
  for (const MinmaxCheck& c : report.minmax_checks) {
    if (quiet && c.pass) continue;
    std::cout << (c.pass ? "PASS " : "FAIL ") << "min-max mip [" << to_string(c.target)
              << encoding_note(c.map_encoding) << "] on " << c.scene << ": ";
    if (!c.error.empty()) {
      std::cout << c.error << "\n";
    } else {
      std::cout << c.mismatched << " of " << c.texels << " nodes off, " << c.levels << " of "
                << c.expected_levels << " levels\n";
    }
  }
  for (const auto& [form, checks] : {std::pair{"function form", &report.function_checks},
                                     std::pair{"deferred mask", &report.deferred_checks}}) {
    for (const EngineFormCheck& c : *checks) {
      if (quiet && c.pass) continue;
      std::cout << (c.pass ? "PASS " : "FAIL ") << form << " " << c.variant << " ["
                << to_string(c.target) << " on " << c.backend
                << (c.map_format == DepthFormat::d32_float
                        ? std::string()
                        : ", " + std::string(to_string(c.map_format)) + " map")
                << "] on "
                << (c.cascade ? "the cascaded stage, cascade " + std::to_string(*c.cascade)
                              : std::string("the camera's stage"))
                << ": ";
      if (!c.error.empty()) {
        std::cout << c.error << "\n";
        continue;
      }
      std::cout << "max error " << c.comparison.max_abs_error << " (tolerance "
                << c.comparison.tolerance << "), " << c.comparison.over_tolerance << " of "
                << c.comparison.compared << " pixels over, camera agreement " << c.camera_agreement
                << "\n";
    }
  }
  for (const VariantRun& v : report.variants) {
    for (const TargetRun& t : v.runs) {
      if (!t.executed) continue;
      if (!t.error.empty()) {
        std::cout << "FAIL " << run_label(v, t) << ": " << t.error << "\n";
        continue;
      }
      double max_error = 0.0;
      double blur_error = 0.0;
      double composite_error = 0.0;
      bool chain = false;
      for (const SceneRun& s : t.scenes) {
        max_error = std::max(max_error, s.comparison.max_abs_error);
        if (s.blur && s.composite) {
          chain = true;
          blur_error = std::max(blur_error, s.blur->max_abs_error);
          composite_error = std::max(composite_error, s.composite->max_abs_error);
        }
      }
      if (quiet && t.pass) continue;
      std::cout << (t.pass ? "PASS " : "FAIL ") << run_label(v, t) << " max error " << max_error;
      // screen_blur: the factor's error above, then the blur's and composite's.
      if (chain) std::cout << ", blur " << blur_error << ", composite " << composite_error;
      std::cout << "\n";
    }
  }
  // Per path: how many (variant, target) runs did not execute, and the first reason.
  std::map<std::string, std::pair<std::size_t, std::string>> skipped;
  for (const VariantRun& v : report.variants) {
    for (const TargetRun& t : v.runs) {
      if (t.executed) continue;
      auto& [count, reason] = skipped[t.backend];
      if (count++ == 0) reason = t.not_executed;
    }
  }
  for (const auto& [backend, why] : skipped) {
    if (quiet) break;
    std::cout << "note: " << why.first << " " << backend << " runs not executed: " << why.second
              << "\n";
  }
  if (report.shard.count > 1) std::cout << "shard " << to_string(report.shard) << ": ";
  std::cout << report.runs - report.failed << " passed, " << report.failed << " failed\n";
}

// Why the library's verify.json is not written, and how to write it.
std::string read_only_note(const Library& library) {
  return library.root.string() + " cannot be written into (" + why_unwritable(library.root) +
         "); pass --results FILE to write them elsewhere";
}

// Where verify.json goes: --results, checked before the checks run, not
// after, when their results would be lost; else the library's own, or, for
// a library no file can be made in (read-only, installed), nowhere: the
// results are still printed. Empty: not written.
Result<std::filesystem::path> results_file(const VerifyArgs& args, const Library& library) {
  if (!args.results.empty()) {
    PENUMBRA_TRY(check_output_file(args.results, "--results"));
    return std::filesystem::path(args.results);
  }
  if (!why_unwritable(library.root).empty()) {
    if (!args.quiet) {
      std::cerr << "penumbra: note: verify.json will not be written: " << read_only_note(library)
                << "\n";
    }
    return std::filesystem::path();
  }
  const std::filesystem::path own = library.root / "verify.json";
  PENUMBRA_TRY(check_output_file(own.string(), ""));
  return own;
}

// What the arguments ask of verify_library, checked before anything is
// read: --path, --map-format, --shard and --target.
Result<VerifyOptions> verify_options(const VerifyArgs& args) {
  PENUMBRA_TRY(check_path_names(args.paths));
  const std::optional<DepthFormat> map_format = parse_depth_format(args.map_format);
  if (!map_format) {
    return make_error(Error::Kind::bad_input, "--map-format " + args.map_format,
                      "unknown depth format; allowed: " + allowed_depth_formats());
  }
  VerifyOptions options{.variants = args.variants,
                        .targets = {},
                        .skipped = args.skipped,
                        .paths = args.paths,
                        .map_format = *map_format,
                        .bytecode = {},
                        .shard = {},
                        .jobs = args.jobs,
                        .progress = stderr_progress(args.quiet)};
  if (!args.shard.empty()) {
    PENUMBRA_TRY_ASSIGN(options.shard, parse_shard(args.shard, "--shard"));
  }
  for (const std::string& name : args.targets) {
    const std::optional<Target> target = parse_target(name);
    if (!target) {
      return make_error(Error::Kind::bad_input, "--target " + name,
                        "unknown target; allowed: " + allowed_targets());
    }
    options.targets.push_back(*target);
  }
  return options;
}

// The run, its results written and printed: the exit code, 0 when every
// check passed, else kExitCheckFailed.
Result<int> run_verify(const VerifyArgs& args) {
  PENUMBRA_TRY_ASSIGN(VerifyOptions options, verify_options(args));
  if (!args.junit.empty()) PENUMBRA_TRY(check_output_file(args.junit, "--junit"));
  PENUMBRA_TRY_ASSIGN(options.bytecode.compiler, find_hlsl_compiler(args.hlsl_compiler));
  PENUMBRA_TRY_ASSIGN(const Library library, load_library(args.library));
  PENUMBRA_TRY_ASSIGN(const std::filesystem::path results, results_file(args, library));
  limit_software_rasterizers(args.jobs);
  if (!args.optimized_jit) skip_software_jit_optimization();
  keep_freed_memory();
  std::vector<std::unique_ptr<Engine>> engines;
  std::vector<Engine*> devices;
  for (int t = 0; t < args.device_threads; ++t) {
    PENUMBRA_TRY_ASSIGN(engines.emplace_back(),
                        Engine::create({.device = args.device, .validation = args.validation},
                                       stderr_diagnostics(args.verbose)));
    devices.push_back(engines.back().get());
  }
  PENUMBRA_TRY_ASSIGN(const VerifyReport verified,
                      verify_library(library, devices, options, stderr_diagnostics(args.verbose)));
  if (!results.empty()) {
    PENUMBRA_TRY(write_file_atomic(results, to_json(verified, library).dump(2) + "\n"));
  }
  if (!args.junit.empty()) {
    PENUMBRA_TRY(write_file_atomic(args.junit, to_junit_xml(to_junit(verified))));
  }
  print_summary(verified, args.quiet);
  if (results.empty()) {
    std::cout << "results: verify.json not written: " << read_only_note(library) << "\n";
    if (!args.junit.empty()) std::cout << "JUnit report: " << args.junit << "\n";
  } else {
    std::cout << "results: " << results.string() << (args.junit.empty() ? "" : ", " + args.junit)
              << "\n";
  }
  return verified.pass() ? kExitOk : kExitCheckFailed;
}

}  // namespace

void add_verify_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<VerifyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "verify", "Run every variant on the Vulkan device and check it against the CPU reference");
  cmd->add_option("library", args->library, "Built library directory")->required();
  cmd->add_option("--device", args->device, "Vulkan device: index or name substring");
  cmd->add_option("--variant", args->variants, "Only these variants (repeatable)");
  cmd->add_option("--target", args->targets, "Only these targets (repeatable)");
  cmd->add_option("--hlsl-compiler", args->hlsl_compiler, kHlslCompilerHelp);
  cmd->add_option("--shard", args->shard,
                  "Only the I-th of N disjoint slices of the checks, I from 1 (docs/scale-out.md)");
  cmd->add_option("--junit", args->junit, "Also write a JUnit XML report to this file");
  cmd->add_option("--results", args->results,
                  "Write the results (verify.json) to this file (default: LIBRARY/verify.json)");
  cmd->add_option("--path", args->paths,
                  "Only these execution paths (repeatable): " + path_names());
  cmd->add_option("--map-format", args->map_format,
                  "Depth image of encoded maps (perspective, perspective_reversed): " +
                      allowed_depth_formats());
  add_skip_flags(cmd, args->skipped);
  cmd->add_flag("--validation", args->validation, "Enable the Vulkan validation layer");
  cmd->add_flag("--optimized-jit", args->optimized_jit,
                "Let Mesa's software rasterizers (lavapipe, llvmpipe) optimize the shaders they "
                "compile, as they do by default; without it verify asks them not to "
                "(GALLIVM_PERF=nopt, unless set), which compiles faster with the same results");
  cmd->add_flag("-v,--verbose", args->verbose, "Print progress notes");
  cmd->add_flag("-q,--quiet", args->quiet,
                "Print no progress and only the failed checks, then the totals");
  add_jobs_option(cmd, args->jobs);
  cmd->add_option("--device-threads", args->device_threads,
                  "Threads that drive the devices, each with devices of its own, so that a "
                  "software driver's shader compiles overlap (default 2; 1 with --jobs 1). "
                  "Results are the same for every N")
      ->check(CLI::Range(1, 16));
  cmd->callback([args, &exit_code] {
    const Result<int> code = run_verify(*args);
    exit_code = code ? *code : report(code.error());
  });
}

}  // namespace penumbra::cli
