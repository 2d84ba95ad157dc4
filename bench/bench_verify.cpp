// penumbra_bench_verify: `penumbra verify` of the default library by two
// builds of penumbra, each on the library it builds itself, an earlier one
// (--baseline, as scripts/bench.sh verify --baseline REV builds it) and this
// one, side by side in one run (alternating, so that a change in the
// machine's load falls on both), and a check of their verify.json: the same
// byte for byte, or, where this build checks more than the earlier one
// (checks added since), every result of the earlier one unchanged in it. Without
// --baseline the baseline is this build run with --baseline-arg's arguments
// (e.g. --optimized-jit): a default of verify's against the old one.
//
// Each verify runs with Mesa's shader cache in a folder of the benchmark's
// own: --cold empties it before every run (a CI runner that starts bare);
// otherwise an untimed run of each build fills it first (a machine that
// keeps ~/.cache between runs).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
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
  std::string manifest;                    // the library's; empty: the shipped default.json
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

// Whether `after` holds everything `before` says: each member of an object
// (an object's too, recursively), each element of an array within some
// element of the other, and equal values. The top-level count of runs is
// left out: it grows with the checks.
bool holds(const nlohmann::json& before, const nlohmann::json& after, bool top = false) {
  if (before.is_object()) {
    if (!after.is_object()) return false;
    for (const auto& [key, value] : before.items()) {
      if (top && key == "runs") continue;
      if (!after.contains(key) || !holds(value, after.at(key))) return false;
    }
    return true;
  }
  if (before.is_array()) {
    if (!after.is_array()) return false;
    return std::ranges::all_of(before, [&](const nlohmann::json& element) {
      return std::ranges::any_of(after, [&](const auto& other) { return holds(element, other); });
    });
  }
  return before == after;
}

// Where `after` first fails to hold `before` (holds() is false): a JSON
// pointer into `before`, and the element no element of `after` holds.
std::string first_unheld(const nlohmann::json& before, const nlohmann::json& after,
                         const std::string& at, bool top = false) {
  if (before.is_object() && after.is_object()) {
    for (const auto& [key, value] : before.items()) {
      if (top && key == "runs") continue;
      if (!after.contains(key)) return at + "/" + key + " (missing)";
      if (!holds(value, after.at(key))) return first_unheld(value, after.at(key), at + "/" + key);
    }
  }
  if (before.is_array() && after.is_array()) {
    for (std::size_t i = 0; i < before.size(); ++i) {
      const auto held = [&](const nlohmann::json& other) { return holds(before[i], other); };
      if (std::ranges::any_of(after, held)) continue;
      return at + "/" + std::to_string(i) + " " + before[i].dump().substr(0, 400);
    }
  }
  return at + ": " + before.dump().substr(0, 200) + " against " + after.dump().substr(0, 200);
}

// Empty when this build's verify.json is the baseline's byte for byte or
// holds all of it; otherwise what differs.
std::string compare_results(const std::string& before, const std::string& after) {
  if (!before.empty() && before == after) return {};
  const auto parsed_before = nlohmann::json::parse(before, nullptr, false);
  const auto parsed_after = nlohmann::json::parse(after, nullptr, false);
  if (parsed_before.is_discarded() || parsed_after.is_discarded()) return "is not JSON";
  if (!holds(parsed_before, parsed_after, true)) {
    return "lacks or changes a result of the baseline's: " +
           first_unheld(parsed_before, parsed_after, "", true);
  }
  std::printf(
      "  this build checks more: its verify.json holds every result of the baseline's "
      "unchanged (%d runs against %d)\n",
      parsed_after.value("runs", 0), parsed_before.value("runs", 0));
  return {};
}

Status run(const Options& options) {
  PENUMBRA_TRY_ASSIGN(const fs::path penumbra, bench::penumbra_executable());
  fs::path manifest = options.manifest;
  if (manifest.empty()) PENUMBRA_TRY_ASSIGN(manifest, bench::default_manifest("default.json"));
  const bench::ScratchRoot scratch("penumbra-bench-verify-");
  const fs::path& root = scratch.path();
  const fs::path log = root / "child.log";  // each child's output, read back when it fails
  const fs::path baseline = options.baseline.empty() ? penumbra : fs::absolute(options.baseline);
  std::vector<Build> builds = {{"baseline", baseline, options.baseline_args, {}, {}, {}},
                               {"this build", penumbra, {}, {}, {}, {}}};
  // Each build builds its own library: index.json's schema moves between
  // commits, and each build's verify reads only its own.
  std::vector<double> build_seconds;
  for (std::size_t b = 0; b < builds.size(); ++b) {
    builds[b].library = root / ("library-" + std::to_string(b));
    builds[b].cache = root / ("shader-cache-" + std::to_string(b));
    PENUMBRA_TRY_ASSIGN(
        build_seconds.emplace_back(),
        bench::seconds_to_succeed({builds[b].penumbra.string(), "build", manifest.string(), "-o",
                                   builds[b].library.string()},
                                  environ, log));
  }
  std::vector<std::string> selection;
  for (const std::string& v : options.variants) selection.insert(selection.end(), {"--variant", v});
  if (options.no_wine) selection.push_back("--no-wine");
  std::printf("%u cores; library built by each in %.1f s and %.1f s; %s; %s; %d repeats\n",
              std::thread::hardware_concurrency(), build_seconds[0], build_seconds[1],
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
    const std::string differs =
        compare_results(bench::read_text(builds[0].library / "verify.json"),
                        bench::read_text(builds[1].library / "verify.json"));
    if (!differs.empty()) {
      return make_error(Error::Kind::internal, "verify.json",
                        "this build's " + differs + " (repeat " + std::to_string(r + 1) + ")");
    }
  }
  const double before = bench::median(builds[0].seconds);
  const double after = bench::median(builds[1].seconds);
  std::printf(
      "\n| verify | baseline (median s) | this build (median s) | speed-up |\n"
      "|---|---|---|---|\n| %s | %.1f | %.1f | %.2fx |\n",
      options.cold ? "cold shader cache" : "warm shader cache", before, after, before / after);
  std::printf("verify.json: every result of the baseline's the same in this build's\n");
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
  app.add_option("--manifest", options.manifest,
                 "the manifest both build their library from (default: the shipped "
                 "default.json; bench/manifests/default-76.json is the one an older baseline "
                 "such as 3bd7d25 can build)")
      ->check(CLI::ExistingFile);
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
