// penumbra_bench_gpu: what each variant costs on the GPU, beside its error
// (docs/performance.md, "GPU cost"). Builds the SPIR-V of a manifest's
// variants in-process, renders the report's stage (reference/stage.hpp) at
// W x H on the Vulkan device, and times each variant's depth pass, min-max
// mip and query pass with timestamp queries (measure_gpu_cost, the report's
// method: the median of R runs after an untimed one). In the same run a
// fetch-only shader with the variants' comparison sampler gives the
// device's texel-rate ceiling, so each variant's rate is also a fraction of
// what this device can fetch, which makes a lavapipe figure comparable too.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <regex>
#include <string>
#include <vector>

#include "bench_files.hpp"
#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/reference/exact_visibility.hpp"
#include "penumbra/reference/stage.hpp"
#include "penumbra/report/figures.hpp"
#include "penumbra/verify/gpu_cost.hpp"

namespace penumbra {
namespace {

struct TempLibrary {
  std::filesystem::path root;
  ~TempLibrary() {
    std::error_code ignored;
    std::filesystem::remove_all(root, ignored);
  }
};

struct Args {
  std::string manifest;               // whose variants are measured
  std::vector<std::string> variants;  // only these; empty = every one
  std::string device;                 // Vulkan device: index or name substring
  int width = 1600;                   // the stage's picture
  int height = 1200;
  int runs = 21;     // timed runs per pass
  int fetches = 64;  // the fetch-only shader's comparisons per pixel
};

// The variants to measure, spirv only; bad_input naming a --variant the
// manifest lacks.
Result<std::vector<Variant>> wanted_variants(const Args& args) {
  PENUMBRA_TRY_ASSIGN(auto all, load_variants(args.manifest));
  std::vector<Variant> wanted;
  for (const std::string& name : args.variants) {
    const auto it =
        std::find_if(all.begin(), all.end(), [&](const Variant& v) { return v.name == name; });
    if (it == all.end()) {
      return make_error(Error::Kind::bad_input, "--variant " + name,
                        "no such variant in " + args.manifest);
    }
    wanted.push_back(*it);
  }
  if (args.variants.empty()) wanted = std::move(all);
  for (Variant& v : wanted) v.targets = {Target::spirv};
  return wanted;
}

Status run(const Args& args) {
  PENUMBRA_TRY_ASSIGN(auto variants, wanted_variants(args));
  TempLibrary temp{std::filesystem::temp_directory_path() /
                   ("penumbra-bench-gpu-" + std::to_string(::getpid()))};
  PENUMBRA_TRY(build_library(variants, temp.root, BuildOptions{.jobs = 2}, ignore_diagnostics()));
  PENUMBRA_TRY_ASSIGN(const Library library, load_library(temp.root));
  PENUMBRA_TRY_ASSIGN(auto engine, Engine::create({.device = args.device, .validation = false},
                                                  ignore_diagnostics()));

  reference::Stage stage = reference::report_stage();
  stage.scene.receivers_width = args.width;
  stage.scene.receivers_height = args.height;
  const reference::StageView view = reference::view(stage, args.width, args.height);
  const FloatImage exact = reference::exact_visibility_image(stage.scene, view);
  const PictureScene scene{stage.scene, view.receivers};
  const GpuCostOptions options{.runs = args.runs};
  const double pixels = double(args.width) * args.height;

  const LibraryVariant* like = nullptr;
  for (const LibraryVariant& v : library.variants) {
    if (!like && reads_comparison_sampler(v)) like = &v;
  }
  if (!like) {
    return make_error(Error::Kind::bad_input, "--variant",
                      "no measured variant samples shadow_cmp, whose sampler state the "
                      "fetch-only ceiling needs; add one (e.g. pcf_grid_k3)");
  }
  PENUMBRA_TRY_ASSIGN(const FetchCeiling ceiling,
                      measure_fetch_ceiling(library, *engine, *like, scene, args.fetches, options));
  const double ceiling_rate =
      gigatexels_per_second(pixels, ceiling.texel_reads_per_pixel, ceiling.query_ms);

  const DeviceInfo& info = engine->device_info();
  std::cout << "GPU cost on the report's stage, " << args.width << "x" << args.height << " ("
            << stage.scene.map_width << "x" << stage.scene.map_height << " map), spirv on "
            << info.name << " (" << info.driver << ")\n"
            << "ms: median GPU time of " << args.runs
            << " runs after an untimed one (timestamp queries); Mpx/s: the query pass; "
               "reads/px: the query's .y over every pixel\n";
  std::printf(
      "fetch-only ceiling: %d comparisons/px with %s's sampler: %.3f ms, %.1f reads/px, "
      "%.3f Gtexel/s\n\n",
      ceiling.fetches, ceiling.sampler_of.c_str(), ceiling.query_ms, ceiling.texel_reads_per_pixel,
      ceiling_rate);
  std::printf("%-32s %-22s %9s %9s %9s %9s %9s %9s %8s %10s\n", "variant", "technique", "depth_ms",
              "mip_ms", "query_ms", "Mpx/s", "reads/px", "Gtexel/s", "/ceiling", "exact_mae");
  for (const LibraryVariant& entry : library.variants) {
    PENUMBRA_TRY_ASSIGN(const GpuCost cost,
                        measure_gpu_cost(library, *engine, entry, scene, options));
    // Only the exact figures are used: the image stands in for the CPU
    // reference, which the benchmark does not compute.
    const FloatImage none(args.width, args.height, 1);
    const report::Figures figures =
        report::measure(view, exact, cost.visibility, cost.visibility, none, cost.texel_reads);
    const double rate = gigatexels_per_second(pixels, cost.texel_reads_per_pixel, cost.query_ms);
    std::printf("%-32s %-22s %9.3f %9.3f %9.3f %9.1f %9.1f %9.3f %8.3f %10.4f\n",
                cost.variant.c_str(), std::string(to_string(cost.technique)).c_str(), cost.depth_ms,
                cost.mip_ms, cost.query_ms, pixels / (cost.query_ms * 1e3),
                cost.texel_reads_per_pixel, rate, ceiling_rate > 0.0 ? rate / ceiling_rate : 0.0,
                figures.exact_penumbra_mae);
  }
  return {};
}

}  // namespace
}  // namespace penumbra

int main(int argc, char** argv) {
  CLI::App app{"penumbra_bench_gpu: each variant's GPU time beside its error"};
  penumbra::Args args;

  std::string size = "1600x1200";
  app.add_option("--manifest", args.manifest,
                 "Manifest whose variants are measured (default: the shipped default.json)");
  app.add_option("--variant", args.variants, "Only this variant (repeatable; default: all)");
  app.add_option("--device", args.device, "Vulkan device: index or name substring");
  app.add_option("--size", size, "The stage's picture, WxH (default 1600x1200)");
  app.add_option("-r,--runs", args.runs, "Timed runs per pass after an untimed one (median)")
      ->check(CLI::Range(20, 1000));
  app.add_option("--fetches", args.fetches, "The fetch-only shader's comparisons per pixel")
      ->check(CLI::Range(1, 1024));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::cerr << "penumbra_bench_gpu: " << e.what() << "\n";
    return 2;
  }
  std::smatch match;
  if (!std::regex_match(size, match, std::regex("([0-9]{1,4})x([0-9]{1,4})")) ||
      std::stoi(match[1]) < 8 || std::stoi(match[2]) < 8) {
    std::cerr << "penumbra_bench_gpu: --size " << size
              << ": expected WxH, each from 8 to 9999 (e.g. 1600x1200)\n";
    return 2;
  }
  if (args.manifest.empty()) {
    auto shipped = penumbra::bench::default_manifest("default.json");
    if (!shipped) {
      std::cerr << "penumbra_bench_gpu: " << shipped.error().to_string() << "\n";
      return 2;
    }
    args.manifest = shipped->string();
  }
  args.width = std::stoi(match[1]);
  args.height = std::stoi(match[2]);
  const penumbra::Status status = penumbra::run(args);
  if (!status) {
    std::cerr << "penumbra_bench_gpu: " << status.error().to_string() << "\n";
    return 2;
  }
  return 0;
}
