// penumbra_bench_jobs: `penumbra verify` and `penumbra report` with
// --jobs 1 against --jobs N on the same library, side by side in one run
// (alternating, so that a change in the machine's load falls on both), and
// a check that every N gives the same results: verify.json, and the report's
// files less their timings (untimed_report_files()).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "bench_child.hpp"
#include "bench_files.hpp"
#include "penumbra/report/report.hpp"

extern char** environ;

namespace penumbra {
namespace {

namespace fs = std::filesystem;

struct Options {
  int jobs = 0;  // N; 0: every core
  int repeats = 3;
  std::vector<std::string> variants;  // empty: one per technique (kDefaultVariants)
  bool all = false;                   // the whole default library
  bool no_wine = false;
};

// One variant of each technique in the default library.
const std::vector<std::string> kDefaultVariants = {"hard",
                                                   "pcf_poisson_p16_poisson",
                                                   "pcss_b16_p16_poisson",
                                                   "minmax_pcf_k16",
                                                   "backprojection",
                                                   "pcss_minmax_p16_poisson",
                                                   "screen_blur_r4",
                                                   "bitmask_backprojection_bits256"};

// What must not depend on --jobs: verify.json, byte for byte, and every
// file of the report less what is timed (untimed_report_files()).
std::map<std::string, std::string> results(const fs::path& library, const fs::path& report) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(report)) {
    if (!entry.is_regular_file()) continue;
    files[entry.path().lexically_relative(report).string()] = bench::read_text(entry.path());
  }
  std::map<std::string, std::string> results;
  for (auto& [name, text] : untimed_report_files(std::move(files))) {
    results["report/" + name] = std::move(text);
  }
  results["verify.json"] = bench::read_text(library / "verify.json");
  return results;
}

// The seconds `argv` takes to exit, its output into `log`.
Result<double> timed(const std::vector<std::string>& argv, const fs::path& log) {
  return bench::seconds_to_succeed(argv, environ, log);
}

Status run(const Options& options) {
  PENUMBRA_TRY_ASSIGN(const fs::path penumbra, bench::penumbra_executable());
  PENUMBRA_TRY_ASSIGN(const fs::path manifest, bench::default_manifest("default.json"));
  const int jobs = options.jobs > 0 ? options.jobs : int(std::thread::hardware_concurrency());
  const bench::ScratchRoot scratch("penumbra-bench-jobs-");
  const fs::path& root = scratch.path();
  const fs::path library = root / "library";
  const fs::path log = root / "child.log";  // each child's output, read back when it fails
  PENUMBRA_TRY_ASSIGN(
      const double build_seconds,
      timed({penumbra.string(), "build", manifest.string(), "-o", library.string()}, log));
  std::vector<std::string> selection;
  if (!options.all) {
    for (const std::string& v : options.variants.empty() ? kDefaultVariants : options.variants) {
      selection.insert(selection.end(), {"--variant", v});
    }
  }
  if (options.no_wine) selection.push_back("--no-wine");

  // Untimed, so that neither N pays alone for what a first run warms up
  // (the page cache, Wine's prefix and its runtimes' first start).
  std::vector<std::string> warm_up = {penumbra.string(), "verify", library.string(), "-q"};
  warm_up.insert(warm_up.end(), selection.begin(), selection.end());
  PENUMBRA_TRY_ASSIGN(const double warm_up_seconds, timed(warm_up, log));
  std::printf(
      "%u cores; penumbra: %s (library built in %.1f s, an untimed verify took %.1f s); %s; "
      "--jobs 1 against --jobs %d, %d repeats\n",
      std::thread::hardware_concurrency(), penumbra.c_str(), build_seconds, warm_up_seconds,
      options.all ? "the whole default library"
                  : (std::to_string(selection.size() / 2) + " variants").c_str(),
      jobs, options.repeats);
  std::map<std::string, std::map<int, std::vector<double>>> seconds;  // command -> jobs -> runs
  std::optional<std::map<std::string, std::string>> first;
  for (int r = 0; r < options.repeats; ++r) {
    for (int j : {1, jobs}) {
      const std::string n = std::to_string(j);
      const fs::path report = root / ("report-" + n);
      std::vector<std::string> verify = {penumbra.string(), "verify", library.string(), "-q",
                                         "--jobs",          n};
      std::vector<std::string> picture = {
          penumbra.string(), "report", library.string(), "-q", "--jobs", n, "-o", report.string()};
      verify.insert(verify.end(), selection.begin(), selection.end());
      picture.insert(picture.end(), selection.begin(), selection.end());
      PENUMBRA_TRY_ASSIGN(seconds["verify"][j].emplace_back(), timed(verify, log));
      PENUMBRA_TRY_ASSIGN(seconds["report"][j].emplace_back(), timed(picture, log));
      auto files = results(library, report);
      if (!first) {
        first = std::move(files);
      } else if (files != *first) {
        for (const auto& [name, text] : files) {
          if (!first->contains(name) || first->at(name) != text) {
            return make_error(Error::Kind::internal, name,
                              "differs between --jobs 1 and --jobs " + std::to_string(jobs));
          }
        }
        return make_error(Error::Kind::internal, "report", "a file is missing with --jobs " + n);
      }
      std::printf("  repeat %d, --jobs %d: verify %.1f s, report %.1f s\n", r + 1, j,
                  seconds["verify"][j].back(), seconds["report"][j].back());
      std::fflush(stdout);
    }
  }
  std::printf(
      "\n| command | --jobs 1 (median s) | --jobs %d (median s) | speed-up |\n|---|---|---|---|\n",
      jobs);
  for (const auto& [command, by_jobs] : seconds) {
    const double one = bench::median(by_jobs.at(1));
    const double many = bench::median(by_jobs.at(jobs));
    std::printf("| %s | %.1f | %.1f | %.2fx |\n", command.c_str(), one, many, one / many);
  }
  std::printf("results identical for --jobs 1 and --jobs %d: %zu files compared\n", jobs,
              first ? first->size() : 0);
  return {};
}

}  // namespace
}  // namespace penumbra

int main(int argc, char** argv) {
  penumbra::Options options;
  CLI::App app{"penumbra_bench_jobs: verify and report with --jobs 1 against --jobs N"};
  app.add_option("-j,--jobs", options.jobs, "N (default: every core)")->check(CLI::PositiveNumber);
  app.add_option("--repeats", options.repeats, "runs of each; the median is printed")
      ->check(CLI::Range(1, 99));
  app.add_option("--variant", options.variants,
                 "only these variants (repeatable; default: one of each technique)");
  app.add_flag("--all", options.all, "the whole default library");
  app.add_flag("--no-wine", options.no_wine, "skip the Direct3D runtimes under Wine");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::fprintf(stderr, "penumbra_bench_jobs: %s\n", e.what());
    return 2;
  }
  const penumbra::Status status = penumbra::run(options);
  if (!status) {
    std::fprintf(stderr, "penumbra_bench_jobs: %s\n", status.error().to_string().c_str());
    return 1;
  }
  return 0;
}
