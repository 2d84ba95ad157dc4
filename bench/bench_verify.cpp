// penumbra_bench_verify: `penumbra verify` of one library by two builds of
// penumbra, an earlier one (--baseline, as scripts/bench.sh verify
// --baseline REV builds it) and this one, side by side in one run
// (alternating, so that a change in the machine's load falls on both), and
// a check that both write the same verify.json, byte for byte. Without
// --baseline the baseline is this build run with --baseline-arg's arguments
// (e.g. --optimized-jit): a default of verify's against the old one.
//
// Each verify runs with Mesa's shader cache in a folder of the benchmark's
// own: --cold empties it before every run (a CI runner that starts bare);
// otherwise an untimed run of each build fills it first (a machine that
// keeps ~/.cache between runs).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "bench_child.hpp"
#include "bench_files.hpp"

extern char** environ;

namespace penumbra {
namespace {

namespace fs = std::filesystem;

struct Options {
  std::string baseline;                    // the earlier build's `penumbra`; empty: this one
  std::vector<std::string> baseline_args;  // more arguments of the baseline's verify
  int repeats = 1;                         // timed runs of each build
  std::vector<std::string> variants;       // empty: the whole default library
  bool cold = false;                       // an empty shader cache for every run
  bool no_wine = false;                    // skip the Direct3D runtimes under Wine
};

struct Build {
  std::string name;  // "baseline", "this build"
  fs::path penumbra;
  std::vector<std::string> args;  // after verify's own
  fs::path library;               // its own copy, where its verify writes verify.json
  fs::path cache;                 // its own shader cache
  std::vector<double> seconds;
};

Result<double> verify(const Build& build, const std::vector<std::string>& selection,
                      const fs::path& log) {
  std::vector<std::string> argv = {build.penumbra.string(), "verify", build.library.string(), "-q"};
  argv.insert(argv.end(), selection.begin(), selection.end());
  argv.insert(argv.end(), build.args.begin(), build.args.end());
  const bench::Environment env(
      {{"MESA_SHADER_CACHE_DIR", build.cache.string()}, {"MESA_SHADER_CACHE_DISABLE", "false"}});
  return bench::seconds_to_succeed(argv, env.get(), log);
}

Status run(const Options& options) {
  PENUMBRA_TRY_ASSIGN(const fs::path penumbra, bench::penumbra_executable());
  PENUMBRA_TRY_ASSIGN(const fs::path manifest, bench::default_manifest("default.json"));
  const bench::ScratchRoot scratch("penumbra-bench-verify-");
  const fs::path& root = scratch.path();
  const fs::path log = root / "child.log";  // each child's output, read back when it fails
  const fs::path library = root / "library";
  PENUMBRA_TRY_ASSIGN(
      const double build_seconds,
      bench::seconds_to_succeed(
          {penumbra.string(), "build", manifest.string(), "-o", library.string()}, environ, log));
  const fs::path baseline = options.baseline.empty() ? penumbra : fs::absolute(options.baseline);
  std::vector<Build> builds = {{"baseline", baseline, options.baseline_args, {}, {}, {}},
                               {"this build", penumbra, {}, {}, {}, {}}};
  for (std::size_t b = 0; b < builds.size(); ++b) {
    builds[b].library = root / ("library-" + std::to_string(b));
    builds[b].cache = root / ("shader-cache-" + std::to_string(b));
    fs::copy(library, builds[b].library, fs::copy_options::recursive);
  }
  std::vector<std::string> selection;
  for (const std::string& v : options.variants) selection.insert(selection.end(), {"--variant", v});
  if (options.no_wine) selection.push_back("--no-wine");
  std::printf("%u cores; library built in %.1f s; %s; %s; %d repeats\n",
              std::thread::hardware_concurrency(), build_seconds,
              options.variants.empty()
                  ? "the whole default library"
                  : (std::to_string(options.variants.size()) + " variants").c_str(),
              options.cold ? "an empty shader cache for every run"
                           : "the shader cache filled by an untimed run of each",
              options.repeats);
  for (const Build& build : builds) {
    std::string args;
    for (const std::string& a : build.args) args += " " + a;
    std::printf("  %s: %s verify%s\n", build.name.c_str(), build.penumbra.c_str(), args.c_str());
    if (!options.cold) PENUMBRA_TRY(verify(build, selection, log));
  }
  std::fflush(stdout);
  for (int r = 0; r < options.repeats; ++r) {
    for (Build& build : builds) {
      if (options.cold) fs::remove_all(build.cache);
      PENUMBRA_TRY_ASSIGN(build.seconds.emplace_back(), verify(build, selection, log));
      std::printf("  repeat %d, %s: %.1f s\n", r + 1, build.name.c_str(), build.seconds.back());
      std::fflush(stdout);
    }
    const std::string baseline_json = bench::read_text(builds[0].library / "verify.json");
    if (baseline_json.empty() ||
        baseline_json != bench::read_text(builds[1].library / "verify.json")) {
      return make_error(
          Error::Kind::internal, "verify.json",
          "differs between the baseline and this build (repeat " + std::to_string(r + 1) + ")");
    }
  }
  const double before = bench::median(builds[0].seconds);
  const double after = bench::median(builds[1].seconds);
  std::printf(
      "\n| verify | baseline (median s) | this build (median s) | speed-up |\n"
      "|---|---|---|---|\n| %s | %.1f | %.1f | %.2fx |\n",
      options.cold ? "cold shader cache" : "warm shader cache", before, after, before / after);
  std::printf("verify.json identical for both builds\n");
  return {};
}

}  // namespace
}  // namespace penumbra

int main(int argc, char** argv) {
  penumbra::Options options;
  CLI::App app{"penumbra_bench_verify: penumbra verify by an earlier build and by this one"};
  app.add_option("--baseline", options.baseline,
                 "the earlier build's penumbra executable (default: this build's)")
      ->check(CLI::ExistingFile);
  app.add_option("--baseline-arg", options.baseline_args,
                 "an argument the baseline's verify gets too (repeatable; "
                 "--baseline-arg=--optimized-jit)");
  app.add_option("--repeats", options.repeats, "timed runs of each; the median is printed")
      ->check(CLI::Range(1, 99));
  app.add_option("--variant", options.variants,
                 "only these variants (repeatable; default: the whole default library)");
  app.add_flag("--cold", options.cold, "empty Mesa's shader cache before every run");
  app.add_flag("--no-wine", options.no_wine, "skip the Direct3D runtimes under Wine");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::fprintf(stderr, "penumbra_bench_verify: %s\n", e.what());
    return 2;
  }
  const penumbra::Status status = penumbra::run(options);
  if (!status) {
    std::fprintf(stderr, "penumbra_bench_verify: %s\n", status.error().to_string().c_str());
    return 1;
  }
  return 0;
}
