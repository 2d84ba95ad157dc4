#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <thread>

#include "build_cache.hpp"
#include "commands.hpp"
#include "exit_codes.hpp"
#include "hlsl_compiler.hpp"
#include "output_file.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/compiler/shaderlib_source.hpp"
#include "penumbra/compiler/targets.hpp"
#include "penumbra/support/atomic_file.hpp"
#include "penumbra/support/content_hash.hpp"
#include "select_variants.hpp"

namespace penumbra::cli {
namespace {

// -j's default: one shader per core.
int default_jobs() {
  return static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 1024u));
}

bool has_hlsl(const std::vector<Variant>& variants) {
  return std::ranges::any_of(variants, [](const Variant& v) {
    return std::ranges::any_of(v.targets, [](Target t) { return traits(t).shader_model != 0; });
  });
}

// A path in a Makefile rule, as Ninja and Make read depfiles.
std::string depfile_escape(const std::string& path) {
  std::string out;
  for (char c : path) {
    if (c == ' ' || c == '#') out += '\\';
    if (c == '$') out += '$';
    out += c;
  }
  return out;
}

// "OUT/index.json: MANIFEST DEP...": the files the build read. Shaderlib files
// only when they are real files (--shaderlib DIR); the embedded copy is part
// of the penumbra binary, which a build system already depends on.
std::string depfile_text(const std::string& out, const std::string& manifest,
                         const ShaderlibSource& shaderlib, const BuildSummary& summary) {
  namespace fs = std::filesystem;
  std::string text = depfile_escape((fs::path(out) / "index.json").string()) + ":";
  text += " " + depfile_escape(fs::absolute(manifest).lexically_normal().string());
  if (shaderlib.on_disk()) {
    for (const std::string& input : summary.inputs) {
      text += " \\\n  " + depfile_escape(fs::absolute(input).lexically_normal().string());
    }
  }
  return text + "\n";
}

// --group I/N: 1 <= I <= N <= 4096.
Result<std::pair<int, int>> parse_group(const std::string& text) {
  int i = 0;
  int n = 0;
  const char* end = text.data() + text.size();
  auto [slash, ec1] = std::from_chars(text.data(), end, i);
  if (ec1 == std::errc() && slash != end && *slash == '/') {
    auto [rest, ec2] = std::from_chars(slash + 1, end, n);
    if (ec2 == std::errc() && rest == end && n >= 1 && n <= 4096 && i >= 1 && i <= n) {
      return std::pair{i, n};
    }
  }
  return make_error(Error::Kind::bad_input, "--group " + text,
                    "expected I/N with 1 <= I <= N <= 4096 (build the I-th of N groups)");
}

// Whether `name` is in group I of N: its name's hash, so that a variant stays
// in its group however the rest of the manifest changes.
bool in_group(const std::string& name, std::pair<int, int> group) {
  const std::uint64_t hash = std::stoull(content_hash(name).substr(0, 15), nullptr, 16);
  return static_cast<int>(hash % static_cast<std::uint64_t>(group.second)) == group.first - 1;
}

// `error`, its place named after `argument` ("--shaderlib DIR: ...").
Error under_argument(Error error, const std::string& argument) {
  error.where = argument + " " + error.where;
  return error;
}

// OUT and --depfile, checked before the work: a build that cannot write
// them must fail before it replaces anything.
Status check_outputs(const std::string& out, const std::string& depfile) {
  if (Status usable = check_output_directory(out); !usable) {
    return under_argument(usable.error(), "-o");
  }
  if (!depfile.empty()) PENUMBRA_TRY(check_output_file(depfile, "--depfile"));
  return {};
}

// "[1234/9000] shaders" on stderr, redrawn at most every 100 ms.
std::function<void(std::size_t, std::size_t)> terminal_progress() {
  auto last = std::make_shared<std::chrono::steady_clock::time_point>();
  return [last](std::size_t done, std::size_t total) {
    const auto now = std::chrono::steady_clock::now();
    if (done < total && now - *last < std::chrono::milliseconds(100)) return;
    *last = now;
    std::cerr << "\r[" << done << "/" << total << "] shaders" << (done == total ? "\r\033[K" : "")
              << std::flush;
  };
}

// `penumbra build`'s arguments, as CLI11 fills them.
struct BuildArgs {
  std::string manifest;
  std::string out;
  int jobs = default_jobs();
  Selection selection;  // --variant, --target, --form
  std::string hlsl_compiler;
  std::string shaderlib;  // empty: the copy built into penumbra
  std::string depfile;    // empty: none
  std::string group;      // "I/N"; empty: every variant
  std::string cache_dir;  // empty: $PENUMBRA_CACHE_DIR, else ~/.cache/penumbra
  bool no_cache = false;
  int hlsl_timeout = 60;  // seconds per HLSL file
  bool keep_going = false;
  bool quiet = false;
  bool verbose = false;
  bool profile = false;  // --profile: each stage's time after the summary
};

// The manifest's variants that --variant, --target, --form and --group select.
Result<std::vector<Variant>> selected_variants(const BuildArgs& args) {
  PENUMBRA_TRY_ASSIGN(std::vector<Variant> all, load_variants(args.manifest));
  PENUMBRA_TRY_ASSIGN(std::vector<Variant> variants,
                      select_variants(std::move(all), args.selection, args.manifest));
  if (!args.group.empty()) {
    PENUMBRA_TRY_ASSIGN(const auto group, parse_group(args.group));
    std::erase_if(variants, [&](const Variant& v) { return !in_group(v.name, group); });
  }
  return variants;
}

Result<std::shared_ptr<const ShaderlibSource>> chosen_shaderlib(const BuildArgs& args) {
  if (args.shaderlib.empty()) return embedded_shaderlib();
  auto dir = shaderlib_directory(args.shaderlib);
  if (!dir) return under_argument(dir.error(), "--shaderlib");
  return std::shared_ptr<const ShaderlibSource>(std::move(*dir));
}

// The build itself, or what the cache's stamp says is current: the summary,
// and whether it came from the stamp.
Result<std::pair<BuildSummary, bool>> build_or_reuse(
    const BuildArgs& args, const std::vector<Variant>& variants,
    const std::filesystem::path& compiler, std::shared_ptr<const ShaderlibSource> shaderlib) {
  const std::filesystem::path cache = cache_directory(args.cache_dir, args.no_cache);
  const BuildStamp stamp = BuildStamp::of(
      cache,
      {variants, args.out,
       args.shaderlib.empty() ? "" : std::filesystem::absolute(args.shaderlib).string(), compiler});
  if (!cache.empty()) {
    if (auto current = stamp.current()) {
      BuildSummary summary;
      summary.inputs = std::move(*current);
      return std::pair{std::move(summary), true};
    }
  }
  const bool on_disk = shaderlib->on_disk();
  const BuildOptions options{
      .jobs = args.jobs,
      .hlsl = {.compiler = compiler, .timeout = std::chrono::seconds(args.hlsl_timeout)},
      .keep_going = args.keep_going,
      .shaderlib = std::move(shaderlib),
      .cache_dir = cache,
      .progress = !args.quiet && isatty(STDERR_FILENO) ? terminal_progress() : nullptr};
  PENUMBRA_TRY_ASSIGN(BuildSummary summary,
                      build_library(variants, args.out, options, stderr_diagnostics(args.verbose)));
  if (!cache.empty()) stamp.record(on_disk ? summary.inputs : std::vector<std::string>{});
  return std::pair{std::move(summary), false};
}

// --profile's table: where the build's thread-seconds went, stage by stage.
void print_profile(const BuildSummary& summary, double wall_seconds, int jobs) {
  double total = 0.0;
  for (const StageTime& row : summary.profile) total += row.seconds;
  std::printf("profile: %.2f s wall on %d threads, %.2f thread-s in stages\n", wall_seconds, jobs,
              total);
  std::printf("%-16s %10s %8s %8s %12s\n", "stage", "thread-s", "share", "runs", "ms/run");
  for (const StageTime& row : summary.profile) {
    const double share = total > 0.0 ? 100.0 * row.seconds / total : 0.0;
    const double per_run =
        row.shaders > 0 ? 1000.0 * row.seconds / static_cast<double>(row.shaders) : 0.0;
    std::printf("%-16s %10.3f %7.1f%% %8zu %12.3f\n", row.stage.c_str(), row.seconds, share,
                row.shaders, per_run);
  }
}

Status run_build(const BuildArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  PENUMBRA_TRY(check_outputs(args.out, args.depfile));
  PENUMBRA_TRY_ASSIGN(const std::vector<Variant> variants, selected_variants(args));
  PENUMBRA_TRY_ASSIGN(const std::filesystem::path compiler, find_hlsl_compiler(args.hlsl_compiler));
  PENUMBRA_TRY_ASSIGN(std::shared_ptr<const ShaderlibSource> shaderlib, chosen_shaderlib(args));
  PENUMBRA_TRY_ASSIGN(const auto built, build_or_reuse(args, variants, compiler, shaderlib));
  const auto& [summary, current] = built;
  if (!args.depfile.empty()) {
    const std::string text = depfile_text(args.out, args.manifest, *shaderlib, summary);
    if (Status written = write_file_atomic(args.depfile, text); !written) {
      Error error = written.error();
      error.where = "--depfile " + args.depfile;
      return error;
    }
  }
  if (!args.quiet && current) {
    std::cout << args.out << " is up to date\n";
  } else if (!args.quiet) {
    std::cout << "built " << summary.variants << " variants (" << summary.files << " shader files, "
              << summary.bytecode << " bytecode files, " << summary.cached
              << " shaders from the cache) into " << args.out << "\n";
  }
  if (args.profile && !current) {
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
    print_profile(summary, wall.count(), args.jobs);
  }
  if (compiler.empty() && has_hlsl(variants)) {
    std::cerr << "penumbra: no Direct3D bytecode made: no HLSL compiler (give --hlsl-compiler "
                 "PATH or PENUMBRA_HLSL_COMPILER; in a penumbra checkout, "
                 "scripts/lib/sid-tools.sh vkd3d installs vkd3d-compiler)\n";
  }
  return {};
}

}  // namespace

void add_build_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<BuildArgs>();
  CLI::App* cmd = app.add_subcommand("build", "Compile every variant of a manifest into OUT");
  cmd->add_option("manifest", args->manifest, "Permutation manifest (JSON)")->required();
  cmd->add_option("-o,--out", args->out, "Output directory (replaced only on success)")->required();
  cmd->add_option("-j,--jobs", args->jobs,
                  "Shaders compiled in parallel (1..1024; default: the number of cores)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--variant", args->selection.variants,
                  "Build only this variant of the manifest (repeatable)");
  cmd->add_option("--target", args->selection.targets, "Build only for this target (repeatable)");
  cmd->add_option("--form", args->selection.forms,
                  "Build only this form: query, deferred or function (repeatable; the passes it "
                  "reads come with it)");
  cmd->add_option("--group", args->group,
                  "Build only group I of N (I/N): the variants whose names hash to it, a "
                  "hermetic part for `penumbra merge` (docs/scale-out.md)");
  cmd->add_option("--cache-dir", args->cache_dir,
                  "Shader cache directory (default: $PENUMBRA_CACHE_DIR, else "
                  "~/.cache/penumbra; docs/cache.md)");
  cmd->add_flag("--no-cache", args->no_cache, "Neither read nor write the shader cache");
  cmd->add_flag("-k,--keep-going", args->keep_going,
                "After a shader fails, compile the others and report every failure "
                "(OUT is still written only when all succeed)");
  cmd->add_option("--shaderlib", args->shaderlib,
                  "Read the shader library's files from DIR (with common/, techniques/ and "
                  "passes/, like the installed share/penumbra/shaderlib) instead of the copy "
                  "built into penumbra");
  cmd->add_option("--depfile", args->depfile,
                  "After a successful build, write a Makefile-style depfile for Ninja or "
                  "CMake (OUT/index.json: the manifest and the --shaderlib files read)");
  cmd->add_option("--hlsl-compiler", args->hlsl_compiler, kHlslCompilerHelp);
  cmd->add_option("--hlsl-timeout", args->hlsl_timeout,
                  "Seconds one HLSL file may take to compile to bytecode")
      ->check(CLI::Range(1, 86400));
  auto* quiet =
      cmd->add_flag("-q,--quiet", args->quiet, "Print only warnings and errors (no summary line)");
  cmd->add_flag("-v,--verbose", args->verbose, "Print progress notes")->excludes(quiet);
  cmd->add_flag("--profile", args->profile,
                "After building, print the thread-seconds each stage took, the cache's and "
                "index.json's (docs/performance.md)");
  cmd->callback([args, &exit_code] {
    const Status s = run_build(*args);
    exit_code = s ? kExitOk : report(s.error());
  });
}

}  // namespace penumbra::cli
