// penumbra_bench_bytecode: how a real Direct3D compiler (vkd3d-compiler)
// takes the HLSL we emit. For each manifest (default: the default library
// and permutations/largest.json, the largest counts a manifest allows), it
// builds the Direct3D targets with bytecode on -j threads (the build's wall
// time), then compiles every HLSL file again alone, R times, and prints the
// median time and the Shader Model 3 instruction slots index.json lists,
// slowest first.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "bench_files.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/compiler/targets.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/support/process.hpp"

namespace penumbra {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Options {
  std::vector<std::filesystem::path> manifests;
  std::filesystem::path compiler;
  int jobs = 2;
  int repeats = 3;
};

// One HLSL file of the library, timed alone.
struct Row {
  std::string file;  // relative to the library root
  std::string profile;
  int slots = 0;  // Shader Model 3 only
  double seconds = 0.0;
};

// Deletes the temporary library however the benchmark ends.
struct TempLibrary {
  std::filesystem::path root;
  ~TempLibrary() {
    std::error_code ignored;
    std::filesystem::remove_all(root, ignored);
  }
};

// `text`, compiled as the build's bytecode stage does (bytecode_format()).
Result<double> median_compile(const Options& options, const std::filesystem::path& text,
                              const BytecodeFormat& format) {
  std::vector<double> times;
  for (int i = 0; i < options.repeats; ++i) {
    const auto start = Clock::now();
    auto run = run_process(
        {options.compiler.string(), "-x", "hlsl", "-p", format.profile, "-b",
         std::string(format.vkd3d_type), "-e", "main", "-o", "/dev/null", text.string()},
        std::chrono::minutes(10));
    if (!run) return run.error();
    if (run->exit_code != 0) {
      return make_error(Error::Kind::compile, text.string(), "vkd3d-compiler: " + run->output);
    }
    times.push_back(seconds_since(start));
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

Status bench_manifest(const Options& options, const std::filesystem::path& manifest) {
  auto variants = load_variants(manifest);
  if (!variants) return variants.error();
  for (Variant& variant : *variants) {
    std::erase_if(variant.targets,
                  [](Target t) { return !bytecode_format(t, ShaderStage::fragment); });
  }
  TempLibrary library_dir{std::filesystem::temp_directory_path() /
                          ("penumbra-bench-bytecode-" + std::to_string(::getpid()))};
  const auto start = Clock::now();
  auto built = build_library(*variants, library_dir.root,
                             {.jobs = options.jobs, .hlsl = {.compiler = options.compiler}},
                             [](const Diagnostic&) {});
  if (!built) return built.error();
  const double build_seconds = seconds_since(start);
  auto library = load_library(library_dir.root);
  if (!library) return library.error();

  std::vector<Row> rows;
  for (const LibraryVariant& variant : library->variants) {
    for (const auto& [pass, by_target] : variant.passes) {
      for (const auto& [target, files] : by_target) {
        for (const auto& [stage, text, bytecode] :
             {std::tuple{ShaderStage::vertex, files.vert, files.vert_bytecode},
              std::tuple{ShaderStage::fragment, files.frag, files.frag_bytecode}}) {
          const auto format = bytecode_format(target, stage);
          if (!bytecode || !format) continue;
          const bool seen = std::any_of(rows.begin(), rows.end(),
                                        [&](const Row& row) { return row.file == text; });
          if (seen) continue;  // a shared pass's file, listed by every variant
          double seconds = 0.0;
          PENUMBRA_TRY_ASSIGN(seconds, median_compile(options, library_dir.root / text, *format));
          rows.push_back({text, bytecode->profile, bytecode->instruction_slots, seconds});
        }
      }
    }
  }
  std::sort(rows.begin(), rows.end(),
            [](const Row& a, const Row& b) { return a.seconds > b.seconds; });
  double total = 0.0;
  int worst_slots = 0;
  for (const Row& row : rows) {
    total += row.seconds;
    worst_slots = std::max(worst_slots, row.slots);
  }
  std::printf("\n%s: %zu variants, %zu Direct3D files\n", manifest.string().c_str(),
              library->variants.size(), rows.size());
  std::printf("build with bytecode, -j %d: %.2f s wall; every file alone: %.2f s in total\n",
              options.jobs, build_seconds, total);
  std::printf("most Shader Model 3 slots: %d (512 every device runs)\n\n", worst_slots);
  std::printf("| file | profile | median s | SM3 slots |\n|---|---|---|---|\n");
  for (const Row& row : rows) {
    const std::string slots = row.slots > 0 ? std::to_string(row.slots) : "-";
    std::printf("| %s | %s | %.3f | %s |\n", row.file.c_str(), row.profile.c_str(), row.seconds,
                slots.c_str());
  }
  return {};
}

}  // namespace
}  // namespace penumbra

int main(int argc, char** argv) {
  penumbra::Options options;
  CLI::App app{"vkd3d-compiler's time and instruction slots for each Direct3D file we emit"};
  const char* env = std::getenv("PENUMBRA_HLSL_COMPILER");
  if (env) options.compiler = env;
  app.add_option("manifests", options.manifests, "manifests to build (default: default, largest)");
  app.add_option("--hlsl-compiler", options.compiler,
                 "vkd3d-compiler (default: $PENUMBRA_HLSL_COMPILER)");
  app.add_option("-j,--jobs", options.jobs, "build threads")->check(CLI::Range(1, 64));
  app.add_option("--repeats", options.repeats, "compiles per file; the median is printed")
      ->check(CLI::Range(1, 99));
  CLI11_PARSE(app, argc, argv);
  const bool named = !options.manifests.empty();
  for (const char* name : {"default.json", "largest.json"}) {
    if (named) break;
    auto manifest = penumbra::bench::default_manifest(name);
    if (!manifest) {
      std::fprintf(stderr, "penumbra_bench_bytecode: %s\n", manifest.error().to_string().c_str());
      return 2;
    }
    options.manifests.push_back(*manifest);
  }
  if (options.compiler.empty()) {
    std::fprintf(stderr,
                 "penumbra_bench_bytecode: --hlsl-compiler: no compiler given and "
                 "PENUMBRA_HLSL_COMPILER is not set\n");
    return 2;
  }
  for (const auto& manifest : options.manifests) {
    const penumbra::Status status = penumbra::bench_manifest(options, manifest);
    if (!status) {
      std::fprintf(stderr, "penumbra_bench_bytecode: %s\n", status.error().to_string().c_str());
      return 1;
    }
  }
  return 0;
}
