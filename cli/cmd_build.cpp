#include <algorithm>
#include <iostream>
#include <thread>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "hlsl_compiler.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/compiler/shaderlib_source.hpp"
#include "penumbra/compiler/targets.hpp"
#include "penumbra/support/atomic_file.hpp"
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

}  // namespace

void add_build_command(CLI::App& app, int& exit_code) {
  struct Args {
    std::string manifest;
    std::string out;
    int jobs = default_jobs();
    std::vector<std::string> variants;
    std::vector<std::string> targets;
    std::string hlsl_compiler;
    std::string shaderlib;
    std::string depfile;
    int hlsl_timeout = 60;
    bool keep_going = false;
    bool quiet = false;
    bool verbose = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("build", "Compile every variant of a manifest into OUT");
  cmd->add_option("manifest", args->manifest, "Permutation manifest (JSON)")->required();
  cmd->add_option("-o,--out", args->out, "Output directory (replaced only on success)")->required();
  cmd->add_option("-j,--jobs", args->jobs,
                  "Shaders compiled in parallel (1..1024; default: the number of cores)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--variant", args->variants,
                  "Build only this variant of the manifest (repeatable)");
  cmd->add_option("--target", args->targets, "Build only for this target (repeatable)");
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
  cmd->callback([args, &exit_code] {
    auto all_variants = load_variants(args->manifest);
    if (!all_variants) {
      exit_code = report(all_variants.error());
      return;
    }
    auto variants =
        select_variants(std::move(*all_variants), args->variants, args->targets, args->manifest);
    if (!variants) {
      exit_code = report(variants.error());
      return;
    }
    auto compiler = find_hlsl_compiler(args->hlsl_compiler);
    if (!compiler) {
      exit_code = report(compiler.error());
      return;
    }
    std::shared_ptr<const ShaderlibSource> shaderlib = embedded_shaderlib();
    if (!args->shaderlib.empty()) {
      auto dir = shaderlib_directory(args->shaderlib);
      if (!dir) {
        Error error = dir.error();
        error.where = "--shaderlib " + error.where;
        exit_code = report(error);
        return;
      }
      shaderlib = std::move(*dir);
    }
    const BuildOptions options{
        .jobs = args->jobs,
        .hlsl = {.compiler = *compiler, .timeout = std::chrono::seconds(args->hlsl_timeout)},
        .keep_going = args->keep_going,
        .shaderlib = shaderlib};
    auto summary = build_library(*variants, args->out, options, stderr_diagnostics(args->verbose));
    if (!summary) {
      exit_code = report(summary.error());
      return;
    }
    if (!args->depfile.empty()) {
      const std::string text = depfile_text(args->out, args->manifest, *shaderlib, *summary);
      if (Status written = write_file_atomic(args->depfile, text); !written) {
        Error error = written.error();
        error.where = "--depfile " + args->depfile;
        exit_code = report(error);
        return;
      }
    }
    if (!args->quiet) {
      std::cout << "built " << summary->variants << " variants (" << summary->files
                << " shader files, " << summary->bytecode << " bytecode files) into " << args->out
                << "\n";
    }
    if (compiler->empty() && has_hlsl(*variants)) {
      std::cerr << "penumbra: no Direct3D bytecode made: no HLSL compiler (give --hlsl-compiler "
                   "PATH or PENUMBRA_HLSL_COMPILER; scripts/lib/setup.sh installs vkd3d-compiler "
                   "with ../shared/tools/fetch-vkd3d)\n";
    }
  });
}

}  // namespace penumbra::cli
