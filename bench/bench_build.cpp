// penumbra_bench_build: how fast the `penumbra` executable builds a library,
// against the same shaders compiled by a chain of separate processes, one
// per tool and shader (glslangValidator, spirv-opt, spirv-val, spirv-cross),
// as a build without penumbra would run them. For each manifest it prints,
// side by side: cold builds at -j1 and -jN (no cache; no Direct3D bytecode
// unless --bytecode), the chain at the same parallelism, a build into a new
// OUT from a warm cache, a rebuild that does nothing, each build's peak RSS,
// index.json's bytes per variant and, with --groups, a split build joined by
// `penumbra merge` and compared with the single build byte for byte. With
// --cold-only, for a manifest too large for all that: cold builds alone, in
// every form, in each --form, and by a --baseline executable (build_cold.hpp).
#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench_child.hpp"
#include "bench_files.hpp"
#include "build_cold.hpp"
#include "build_runs.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/library/library.hpp"
#include "penumbra/model/target_traits.hpp"

extern char** environ;

namespace penumbra {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Options {
  std::vector<std::filesystem::path> manifests;
  int jobs = 1;                    // N: build threads, chain workers and group processes at once
  int chain_sample = 1;            // the chain runs on every K-th shader; its time is scaled up
  int groups = 0;                  // split build: G `penumbra build --group I/G`; 0: none
  bool bytecode = false;           // also a cold build with vkd3d-compiler, timed apart
  bool skip_j1 = false;            // no -j1 build or chain (manifests too large to build twice)
  bool cold_only = false;          // cold builds only, side by side (build_cold.hpp)
  std::vector<std::string> forms;  // with cold_only: also a build in each form alone
  std::filesystem::path baseline;  // with cold_only: also this executable's build
  std::filesystem::path hlsl_compiler = {};  // with --bytecode
  std::filesystem::path penumbra = {};       // the executable measured (bench::penumbra_executable)
};

// Deletes the benchmark's folder however it ends.
struct TempDir {
  std::filesystem::path root;
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(root, ignored);
  }
};

using bench::BuildRunner;
using bench::Measured;
using bench::print_row;
using bench::read_text;
using bench::run_child;

// A program on PATH, as a path (posix_spawn does not search).
std::filesystem::path find_program(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(dir) / name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

// One shader of the library, as the chain compiles it.
struct ChainShader {
  std::filesystem::path source;  // preprocessed GLSL, written before any timing
  ShaderStage stage = ShaderStage::fragment;
  Target target = Target::spirv;
};

// The shader files a library lists, each once (every variant lists the
// shared ones), in index order: how many, and every `sample`-th of them
// with its preprocessed source written under `dir`.
struct ChainPlan {
  std::size_t total = 0;
  std::vector<ChainShader> sampled;
};

Result<ChainPlan> plan_chain(const std::filesystem::path& manifest, const Library& library,
                             int sample, const std::filesystem::path& dir) {
  auto variants = load_variants(manifest);
  if (!variants) return variants.error();
  std::map<std::string, const Variant*> by_name;
  for (const Variant& variant : *variants) by_name[variant.name] = &variant;
  std::filesystem::create_directories(dir);
  ChainPlan plan;
  std::set<std::string> seen;
  // One file of the library; its preprocessed text from `preprocess` when sampled.
  const auto add = [&](const std::string& file, ShaderStage stage, Target target,
                       const auto& preprocess) -> Status {
    if (!seen.insert(file).second) return {};
    if (plan.total++ % static_cast<std::size_t>(sample) != 0) return {};
    PENUMBRA_TRY_ASSIGN(const std::string text, preprocess());
    const std::filesystem::path source =
        dir / (std::to_string(plan.sampled.size()) + "." + std::string(stage_key(stage)));
    std::ofstream(source, std::ios::binary) << text;
    plan.sampled.push_back({source, stage, target});
    return {};
  };
  for (const LibraryVariant& built : library.variants) {
    const Variant& variant = *by_name.at(built.variant.name);
    for (const auto& [pass, by_target] : built.passes) {
      for (const auto& [target, files] : by_target) {
        for (const auto& [stage, file] : {std::pair{ShaderStage::vertex, files.vert},
                                          std::pair{ShaderStage::fragment, files.frag}}) {
          PENUMBRA_TRY(add(file, stage, target, [&, target = target, pass = pass, stage = stage] {
            return preprocess_shader(variant, target, pass, stage);
          }));
        }
      }
    }
    // The function forms: the chain compiles each as a fragment shader.
    for (const auto& [target, form] : built.function) {
      PENUMBRA_TRY(add(form.file, ShaderStage::fragment, target,
                       [&, target = target] { return preprocess_function(variant, target); }));
    }
  }
  return plan;
}

// The separate tools, found on PATH.
struct ChainTools {
  std::filesystem::path glslang, opt, val, cross;
};

// The processes for one shader, as our pipeline's stages: SPIR-V 1.0 for
// Vulkan 1.0, spirv-opt's dead-code passes of stages/optimize.cpp,
// validation, then the target's text with SPIRV-Cross's options of
// stages/cross_compile.cpp (none for spirv).
std::vector<std::vector<std::string>> chain_commands(const ChainTools& tools,
                                                     const ChainShader& shader,
                                                     const std::filesystem::path& scratch) {
  const std::string compiled = (scratch / "compiled.spv").string();
  const std::string optimized = (scratch / "optimized.spv").string();
  std::vector<std::vector<std::string>> commands = {
      {tools.glslang.string(), "-V", "--target-env", "vulkan1.0", "-S",
       std::string(stage_key(shader.stage)), shader.source.string(), "-o", compiled},
      {tools.opt.string(), "--target-env=vulkan1.0", "--fold-spec-const-op-composite",
       "--eliminate-dead-branches", "--eliminate-dead-functions",
       "--eliminate-dead-code-aggressive", "--eliminate-dead-const", "--cfg-cleanup", compiled,
       "-o", optimized},
      {tools.val.string(), "--target-env", "vulkan1.0", optimized}};
  if (shader.target == Target::spirv) return commands;
  std::vector<std::string> cross = {tools.cross.string(), optimized, "--output",
                                    (scratch / "text").string()};
  const bool vertex = shader.stage == ShaderStage::vertex;
  const TargetTraits target = traits(shader.target);
  if (target.is_hlsl) {
    cross.insert(cross.end(),
                 {"--hlsl", "--shader-model", std::to_string(target.shader_model * 10)});
    if (vertex) cross.emplace_back("--flip-vert-y");
  } else {
    if (shader.target == Target::glsl450) cross.insert(cross.end(), {"--version", "450"});
    if (shader.target == Target::glsl330) {
      cross.insert(cross.end(), {"--version", "330", "--no-420pack-extension"});
    }
    if (shader.target == Target::essl300) cross.insert(cross.end(), {"--version", "300", "--es"});
    if (vertex) cross.emplace_back("--fixup-clipspace");
  }
  commands.push_back(std::move(cross));
  return commands;
}

// Runs the chain for every shader on `workers` threads: the wall time.
Result<double> run_chain(const ChainTools& tools, const std::vector<ChainShader>& shaders,
                         int workers, const std::filesystem::path& dir) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex error_mutex;
  std::optional<Error> error;
  char* const* env = environ;
  auto worker = [&](int id) {
    const std::filesystem::path scratch = dir / ("worker" + std::to_string(id));
    std::filesystem::create_directories(scratch);
    for (std::size_t i = next++; i < shaders.size() && !failed; i = next++) {
      for (const auto& command : chain_commands(tools, shaders[i], scratch)) {
        auto run = run_child(command, env, scratch / "log");
        if (run && run->exit_code == 0) continue;
        const std::scoped_lock lock(error_mutex);
        failed = true;
        if (!error) {
          error = run ? make_error(Error::Kind::compile, shaders[i].source.string(),
                                   command[0] + " failed:\n" + run->output)
                      : run.error();
        }
        return;
      }
    }
  };
  const auto start = Clock::now();
  {
    std::vector<std::jthread> pool;
    for (int w = 1; w < workers; ++w) pool.emplace_back(worker, w);
    worker(0);
  }
  if (error) return *error;
  return seconds_since(start);
}

// Every regular file under `dir`, relative to it, sorted.
std::vector<std::filesystem::path> files_under(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file()) files.push_back(entry.path().lexically_relative(dir));
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The first difference between two folders' files, or none.
std::optional<std::string> first_difference(const std::filesystem::path& a,
                                            const std::filesystem::path& b) {
  const auto files = files_under(a);
  if (files != files_under(b)) return "the folders hold different files";
  for (const auto& file : files) {
    if (read_text(a / file) != read_text(b / file)) return file.string() + " differs";
  }
  return std::nullopt;
}

// What du reports: the blocks the files under `dir` take.
std::uintmax_t disk_usage(const std::filesystem::path& dir) {
  std::uintmax_t bytes = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    struct stat st {};
    if (::lstat(entry.path().c_str(), &st) == 0)
      bytes += static_cast<std::uintmax_t>(st.st_blocks) * 512;
  }
  return bytes;
}

// The split build: G `penumbra build --group I/G -j1` processes, N at a time,
// then `penumbra merge`.
struct SplitBuild {
  Measured groups;  // wall time of all groups; the largest peak RSS of one
  Measured merge;
  std::optional<std::string> difference;  // from the single build; none: identical
};

Result<SplitBuild> split_build(const BuildRunner& bench, const Options& options,
                               const std::filesystem::path& manifest,
                               const std::filesystem::path& single) {
  const std::filesystem::path parts = bench.root() / "parts";
  std::filesystem::create_directories(parts);
  std::atomic<int> next{1};
  std::mutex mutex;
  std::optional<Error> error;
  SplitBuild split;
  auto worker = [&] {
    for (int group = next++; group <= options.groups; group = next++) {
      const std::string spec = std::to_string(group) + "/" + std::to_string(options.groups);
      auto part = bench.build(manifest, parts / std::to_string(group), 1,
                              {"--group", spec, "--no-cache", "-q"});
      const std::scoped_lock lock(mutex);
      if (!part) {
        if (!error) error = part.error();
        return;
      }
      split.groups.peak_rss_kb = std::max(split.groups.peak_rss_kb, part->peak_rss_kb);
    }
  };
  const auto start = Clock::now();
  {
    std::vector<std::jthread> pool;
    for (int w = 1; w < std::min(options.jobs, options.groups); ++w) pool.emplace_back(worker);
    worker();
  }
  if (error) return *error;
  split.groups.seconds = seconds_since(start);
  std::vector<std::string> args = {"merge"};
  for (int group = 1; group <= options.groups; ++group) {
    args.push_back((parts / std::to_string(group)).string());
  }
  const std::filesystem::path merged = bench.root() / "merged";
  args.insert(args.end(), {"-o", merged.string()});
  PENUMBRA_TRY_ASSIGN(split.merge, bench.penumbra(std::move(args), "merge"));
  split.difference = first_difference(single, merged);
  std::filesystem::remove_all(parts);
  std::filesystem::remove_all(merged);
  return split;
}

Status bench_manifest(const Options& options, const ChainTools& tools,
                      const std::filesystem::path& manifest) {
  TempDir temp{std::filesystem::temp_directory_path() /
               ("penumbra-bench-build-" + std::to_string(::getpid()))};
  const BuildRunner bench(temp.root, options.penumbra);
  const std::string j = "-j" + std::to_string(options.jobs);
  const std::vector<std::string> no_cache = {"--no-cache"};

  std::optional<Measured> cold1;
  if (!options.skip_j1) {
    PENUMBRA_TRY_ASSIGN(cold1, bench.build(manifest, temp.root / "cold-j1", 1, no_cache));
    std::filesystem::remove_all(temp.root / "cold-j1");
  }
  const std::filesystem::path single = temp.root / "cold";
  Measured cold;
  PENUMBRA_TRY_ASSIGN(cold, bench.build(manifest, single, options.jobs, no_cache));
  const std::size_t shaders = cold.counts.files;

  std::optional<Measured> with_bytecode;
  if (options.bytecode) {
    PENUMBRA_TRY_ASSIGN(with_bytecode, bench.build(manifest, temp.root / "bytecode", options.jobs,
                                                   {"--no-cache", "--hlsl-compiler",
                                                    options.hlsl_compiler.string()}));
    std::filesystem::remove_all(temp.root / "bytecode");
  }

  // The cache: filled by one cold build, then read by a build into a new
  // OUT, then a rebuild of that OUT that finds its stamp and does nothing.
  const std::filesystem::path cache = temp.root / "cache";
  const std::vector<std::string> cached = {"--cache-dir", cache.string()};
  Measured fill;
  Measured warm;
  Measured noop;
  PENUMBRA_TRY_ASSIGN(fill, bench.build(manifest, temp.root / "fill", options.jobs, cached));
  const std::uintmax_t cache_bytes = disk_usage(cache);
  PENUMBRA_TRY_ASSIGN(warm, bench.build(manifest, temp.root / "warm", options.jobs, cached));
  PENUMBRA_TRY_ASSIGN(noop, bench.build(manifest, temp.root / "warm", options.jobs, cached));
  std::filesystem::remove_all(temp.root / "fill");
  std::filesystem::remove_all(temp.root / "warm");

  auto library = load_library(single);
  if (!library) return library.error();
  ChainPlan plan;
  PENUMBRA_TRY_ASSIGN(
      plan, plan_chain(manifest, *library, options.chain_sample, temp.root / "chain-sources"));
  if (plan.total != shaders) {
    return make_error(Error::Kind::internal, (single / "index.json").string(),
                      "lists " + std::to_string(plan.total) + " shader files; penumbra built " +
                          std::to_string(shaders));
  }
  // The chain's time for every shader, from the sampled ones.
  const double scale = static_cast<double>(plan.total) / static_cast<double>(plan.sampled.size());
  std::optional<double> chain1;
  if (!options.skip_j1) {
    double seconds = 0.0;
    PENUMBRA_TRY_ASSIGN(seconds, run_chain(tools, plan.sampled, 1, temp.root / "chain"));
    chain1 = seconds * scale;
  }
  double chain_n = 0.0;
  PENUMBRA_TRY_ASSIGN(chain_n, run_chain(tools, plan.sampled, options.jobs, temp.root / "chain"));
  chain_n *= scale;

  std::optional<SplitBuild> split;
  if (options.groups > 0) {
    PENUMBRA_TRY_ASSIGN(split, split_build(bench, options, manifest, single));
  }
  const auto index_bytes = std::filesystem::file_size(single / "index.json");
  const std::size_t variants = cold.counts.variants;

  std::printf("\n%s: %zu variants, %zu shaders; -j%d\n\n",
              std::filesystem::relative(manifest).string().c_str(), variants, shaders,
              options.jobs);
  std::printf("| run | wall s | shaders/s | peak RSS MiB | |\n|---|---|---|---|---|\n");
  if (cold1) print_row("cold -j1, no cache", cold1->seconds, shaders, cold1->peak_rss_kb);
  print_row("cold " + j + ", no cache", cold.seconds, shaders, cold.peak_rss_kb);
  if (with_bytecode) {
    print_row("cold " + j + ", no cache, with bytecode", with_bytecode->seconds, shaders,
              with_bytecode->peak_rss_kb,
              std::to_string(with_bytecode->counts.bytecode) + " bytecode files");
  }
  print_row("cold " + j + ", filling an empty cache", fill.seconds, shaders, fill.peak_rss_kb);
  print_row("warm cache, new OUT, " + j, warm.seconds, shaders, warm.peak_rss_kb,
            std::to_string(warm.counts.cached) + " of " + std::to_string(shaders) +
                " shaders from the cache");
  print_row("no-op rebuild of that OUT", noop.seconds, 0, noop.peak_rss_kb,
            noop.counts.up_to_date ? "OUT is up to date" : "NOT up to date: it built again");
  const std::string sampled = options.chain_sample > 1
                                  ? ", sampled: " + std::to_string(plan.sampled.size()) + " of " +
                                        std::to_string(plan.total) + " shaders, scaled"
                                  : "";
  if (chain1) print_row("chain -j1" + sampled, *chain1, shaders, 0);
  print_row("chain " + j + sampled, chain_n, shaders, 0);
  if (split) {
    const std::string groups = std::to_string(options.groups) + " groups, " +
                               std::to_string(std::min(options.jobs, options.groups)) +
                               " at a time, -j1 each";
    print_row(groups, split->groups.seconds, shaders, split->groups.peak_rss_kb);
    print_row("penumbra merge", split->merge.seconds, 0, split->merge.peak_rss_kb);
  }

  std::printf("\n");
  if (cold1) {
    std::printf("speed-up -j%d/-j1: %.2fx\n", options.jobs, cold1->seconds / cold.seconds);
    std::printf("chain/penumbra at -j1: %.1fx\n", *chain1 / cold1->seconds);
  }
  std::printf("chain/penumbra at %s: %.1fx (goal: 10x or more)\n", j.c_str(),
              chain_n / cold.seconds);
  if (with_bytecode) {
    std::printf("bytecode (vkd3d-compiler): +%.2f s at %s for %zu files\n",
                with_bytecode->seconds - cold.seconds, j.c_str(), with_bytecode->counts.bytecode);
  }
  std::printf("no-op rebuild: %.3f s (goal for the default library: under 0.1 s)\n", noop.seconds);
  std::printf("index.json: %ju bytes, %ju bytes/variant\n",
              static_cast<std::uintmax_t>(index_bytes),
              static_cast<std::uintmax_t>(index_bytes / std::max<std::size_t>(variants, 1)));
  std::printf("cache after the cold build: %.1f MiB on disk\n",
              static_cast<double>(cache_bytes) / (1024.0 * 1024.0));
  if (split) {
    std::printf("split build: %.2f s in all; merged library %s\n",
                split->groups.seconds + split->merge.seconds,
                split->difference ? ("DIFFERS from the single build: " + *split->difference).c_str()
                                  : "equals the single build byte for byte");
  }
  return {};
}

// "AMD EPYC ..." from /proc/cpuinfo.
std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("model name")) return line.substr(line.find(':') + 2);
  }
  return "unknown CPU";
}

std::string load_average() {
  std::string text = read_text("/proc/loadavg");
  return text.substr(0, text.find(' ', text.find(' ', text.find(' ') + 1) + 1));
}

}  // namespace
}  // namespace penumbra

int main(int argc, char** argv) {
  penumbra::Options options;
  options.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  CLI::App app{
      "penumbra build's cold, warm and no-op times, memory and index size, against "
      "a chain of separate tools"};
  app.add_option("--manifest", options.manifests,
                 "manifest to build, repeatable (default: permutations/default.json)")
      ->check(CLI::ExistingFile);
  app.add_option("-j,--jobs", options.jobs, "N: build threads, chain workers (default: cores)")
      ->check(CLI::Range(1, 256));
  app.add_option("--chain-sample", options.chain_sample,
                 "time the chain on every K-th shader and scale it up")
      ->check(CLI::Range(1, 1000000));
  app.add_option("--groups", options.groups,
                 "also a split build: G `--group I/G` builds, N at a time, and penumbra merge")
      ->check(CLI::Range(1, 4096));
  app.add_flag("--bytecode", options.bytecode,
               "also a cold build with vkd3d-compiler ($PENUMBRA_HLSL_COMPILER), timed apart");
  app.add_flag("--skip-j1", options.skip_j1, "no -j1 build or chain, for large manifests");
  auto* cold_only = app.add_flag(
      "--cold-only", options.cold_only,
      "only cold builds at -jN, side by side: every form, each --form, the --baseline's");
  app.add_option("--form", options.forms, "with --cold-only: also a build in this form alone")
      ->needs(cold_only);
  app.add_option("--baseline", options.baseline,
                 "with --cold-only: also a build by this penumbra executable (an older one)")
      ->needs(cold_only)
      ->check(CLI::ExistingFile);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::fprintf(stderr, "penumbra_bench_build: %s\n", e.what());
    return 2;
  }
  auto penumbra = penumbra::bench::penumbra_executable();
  auto shipped = penumbra::bench::default_manifest("default.json");
  if (!penumbra || (options.manifests.empty() && !shipped)) {
    std::fprintf(stderr, "penumbra_bench_build: %s\n",
                 (!penumbra ? penumbra.error() : shipped.error()).to_string().c_str());
    return 2;
  }
  options.penumbra = *penumbra;
  if (options.manifests.empty()) options.manifests = {*shipped};
  if (options.bytecode) {
    const char* env = std::getenv("PENUMBRA_HLSL_COMPILER");
    if (env && *env) options.hlsl_compiler = env;
    if (options.hlsl_compiler.empty() || ::access(options.hlsl_compiler.c_str(), X_OK) != 0) {
      std::fprintf(stderr,
                   "penumbra_bench_build: --bytecode: PENUMBRA_HLSL_COMPILER names no "
                   "vkd3d-compiler (scripts/bench.sh build --bytecode installs one)\n");
      return 2;
    }
  }
  const penumbra::ChainTools tools{
      penumbra::find_program("glslangValidator"), penumbra::find_program("spirv-opt"),
      penumbra::find_program("spirv-val"), penumbra::find_program("spirv-cross")};
  for (const auto& [tool, package] : {std::pair{&tools.glslang, "glslangValidator (glslang-tools)"},
                                      std::pair{&tools.opt, "spirv-opt (spirv-tools)"},
                                      std::pair{&tools.val, "spirv-val (spirv-tools)"},
                                      std::pair{&tools.cross, "spirv-cross (spirv-cross)"}}) {
    if (tool->empty()) {
      std::fprintf(stderr, "penumbra_bench_build: %s is not on PATH\n", package);
      return 1;
    }
  }
  std::printf("%u cores (%s), load average %s; penumbra: %s\n", std::thread::hardware_concurrency(),
              penumbra::cpu_model().c_str(), penumbra::load_average().c_str(),
              options.penumbra.c_str());
  for (const auto& manifest : options.manifests) {
    const penumbra::Status status =
        options.cold_only
            ? penumbra::bench::bench_cold_builds(
                  {options.jobs, options.forms, options.penumbra, options.baseline}, manifest)
            : penumbra::bench_manifest(options, tools, manifest);
    if (!status) {
      std::fprintf(stderr, "penumbra_bench_build: %s\n", status.error().to_string().c_str());
      return 1;
    }
    std::printf("load average after: %s\n", penumbra::load_average().c_str());
  }
  return 0;
}
