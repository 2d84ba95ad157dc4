// penumbra_bench_minmax: minmax_pcf's min-max traversal against brute force
// on the Vulkan device (docs/runtime.md, "Benchmark"). Builds the variants
// in-process into a temporary library (spirv), renders a scene with large
// lit and shadowed regions with the library's depth pass, builds the mip,
// runs each variant R times and prints texel reads and GPU times side by side.
// The mip build and each variant run once first, untimed: a driver may
// compile a pipeline lazily on its first use, inside the timestamps.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "penumbra/compiler/build.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/model/shadow_params.hpp"
#include "penumbra/reference/scene.hpp"
#include "penumbra/verify/library_programs.hpp"
#include "penumbra/vulkan/engine.hpp"

namespace penumbra {
namespace {

constexpr int kKernels[] = {8, 16, 32, 64};

constexpr const char* kManifest = R"({
  "schema": 1,
  "targets": ["spirv"],
  "sets": [
    {"technique": "minmax_pcf", "kernel": [8, 16, 32, 64]},
    {"technique": "minmax_pcf", "kernel": [8, 16, 32, 64], "traversal": "brute_force"}
  ]})";

// 512 x 512, the NVIDIA PCSS whitepaper's light: the left half of the map under an
// occluder at z = 12, a square of the right half under one at z = 13, the
// rest open over a flat receiver at z = 16.
reference::Scene bench_scene() {
  reference::Scene scene;
  scene.name = "halves";
  scene.occluders = {{-6.0, -6.0, 0.0, 6.0, 12.0}, {0.5, 0.5, 2.0, 2.0, 13.0}};
  scene.plane_z0 = 16.0;
  scene.map_width = 512;
  scene.map_height = 512;
  scene.receivers_width = 512;
  scene.receivers_height = 512;
  return scene;
}

// Deletes the temporary library however the benchmark ends.
struct TempLibrary {
  std::filesystem::path root;
  ~TempLibrary() {
    std::error_code ignored;
    std::filesystem::remove_all(root, ignored);
  }
};

std::optional<double> median(std::vector<double> values) {
  if (values.empty()) return std::nullopt;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

struct Measured {
  double mean_reads = 0.0;
  double max_reads = 0.0;
  std::optional<double> median_ms;
  FloatImage visibility;
};

class Bench {
 public:
  Bench(const Library& library, Engine& engine, int repeats)
      : library_(library), engine_(engine), repeats_(repeats) {}

  Result<PassProgram> program(const std::string& variant, PassKind pass) const {
    const LibraryVariant* entry = library_.find(variant);
    if (!entry) return make_error(Error::Kind::internal, variant, "not in the bench library");
    auto loaded = load_executable(library_, *entry, pass, Target::spirv);
    if (!loaded) return loaded.error();
    return loaded->program;
  }

  Status prepare(const reference::Scene& scene) {
    params_ = shadow_params(
        scene.light,
        {scene.map_width, scene.map_height, scene.receivers_width, scene.receivers_height},
        depth_scale_for(scene.far_z));
    auto depth = program("minmax_pcf_k8", PassKind::depth);
    if (!depth) return depth.error();
    auto map = engine_.render_depth(*depth, reference::triangles(scene), scene.map_width,
                                    scene.map_height, params_);
    if (!map) return map.error();
    map_ = *map;
    receivers_ = reference::receivers(scene, scene.receivers_width, scene.receivers_height);
    return {};
  }

  // Builds the mip once untimed, then R times (each replaces the last); the
  // median GPU time of the R.
  Result<MinmaxBuild> build_mip() {
    auto init = program("minmax_pcf_k8", PassKind::minmax_init);
    if (!init) return init.error();
    auto reduce = program("minmax_pcf_k8", PassKind::minmax_reduce);
    if (!reduce) return reduce.error();
    auto last = engine_.build_minmax(*map_, *init, *reduce, params_);
    if (!last) return last.error();
    std::vector<double> times;
    for (int r = 0; r < repeats_; ++r) {
      last = engine_.build_minmax(*map_, *init, *reduce, params_);
      if (!last) return last.error();
      if (last->gpu_ms) times.push_back(*last->gpu_ms);
    }
    last->gpu_ms = median(times);
    return last;
  }

  // The texel reads and image of an untimed first run, then the median GPU
  // time of R more.
  Result<Measured> measure(const std::string& variant) {
    auto query = program(variant, PassKind::query);
    if (!query) return query.error();
    auto first = engine_.run_query_output(*query, *map_, receivers_, params_);
    if (!first) return first.error();
    Measured measured;
    double sum = 0.0;
    for (float reads : first->texel_reads.data) {
      sum += reads;
      measured.max_reads = std::max(measured.max_reads, double(reads));
    }
    measured.mean_reads = sum / double(first->texel_reads.pixel_count());
    measured.visibility = std::move(first->visibility);
    std::vector<double> times;
    for (int r = 0; r < repeats_; ++r) {
      auto output = engine_.run_query_output(*query, *map_, receivers_, params_);
      if (!output) return output.error();
      if (output->gpu_ms) times.push_back(*output->gpu_ms);
    }
    measured.median_ms = median(times);
    return measured;
  }

 private:
  const Library& library_;
  Engine& engine_;
  int repeats_;
  ParamBlock params_;
  std::shared_ptr<ShadowMap> map_;
  FloatImage receivers_;
};

std::string format(const char* pattern, double value) {
  char text[32];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string ms(const std::optional<double>& value) {
  return value ? format("%.3f", *value) : "n/a";
}

std::string ratio(const std::optional<double>& num, const std::optional<double>& den) {
  return num && den && *den > 0.0 ? format("%.1fx", *num / *den) : "n/a";
}

Status run(const std::string& device, int repeats) {
  TempLibrary temp{std::filesystem::temp_directory_path() /
                   ("penumbra-bench-" + std::to_string(::getpid()))};
  auto manifest = parse_manifest(kManifest, "penumbra_bench_minmax");
  if (!manifest) return manifest.error();
  auto variants = expand(*manifest);
  if (!variants) return variants.error();
  auto built = build_library(*variants, temp.root, BuildOptions{}, ignore_diagnostics());
  if (!built) return built.error();
  auto library = load_library(temp.root);
  if (!library) return library.error();
  auto engine = Engine::create({.device = device, .validation = false}, ignore_diagnostics());
  if (!engine) return engine.error();

  const reference::Scene scene = bench_scene();
  Bench bench(*library, **engine, repeats);
  PENUMBRA_TRY(bench.prepare(scene));
  auto mip = bench.build_mip();
  if (!mip) return mip.error();

  const DeviceInfo& info = (*engine)->device_info();
  std::cout << "minmax_pcf, spirv, on " << info.name << " (" << info.driver << ")\n"
            << "scene: " << scene.map_width << "x" << scene.map_height << " map, "
            << scene.receivers_width << "x" << scene.receivers_height
            << " receivers on a flat plane; " << repeats
            << " timed runs per variant after an untimed one, GPU times are medians of "
               "timestamp queries\n"
            << "min-max mip build: " << mip->levels << " levels, " << ms(mip->gpu_ms)
            << " ms GPU\n\n";
  std::printf("%4s | %23s | %15s | %21s | %11s | %11s | %s\n", "K", "mean reads/px mip/brute",
              "max mip/brute", "GPU ms mip/brute", "reads brute", "time brute", "same");
  std::printf("%4s | %23s | %15s | %21s | %11s | %11s | %s\n", "", "", "", "", "/ mip", "/ mip",
              "result");
  for (int k : kKernels) {
    const std::string name = "minmax_pcf_k" + std::to_string(k);
    auto tree = bench.measure(name);
    if (!tree) return tree.error();
    auto brute = bench.measure(name + "_brute_force");
    if (!brute) return brute.error();
    const bool same = tree->visibility.data == brute->visibility.data;
    std::printf("%4d | %10.1f / %10.1f | %6.0f / %6.0f | %9s / %9s | %11s | %11s | %s\n", k,
                tree->mean_reads, brute->mean_reads, tree->max_reads, brute->max_reads,
                ms(tree->median_ms).c_str(), ms(brute->median_ms).c_str(),
                ratio(brute->mean_reads, tree->mean_reads).c_str(),
                ratio(brute->median_ms, tree->median_ms).c_str(), same ? "yes" : "NO");
    if (k != kKernels[std::size(kKernels) - 1]) continue;
    const auto count = [&](float value) {
      return std::count(tree->visibility.data.begin(), tree->visibility.data.end(), value);
    };
    const double pixels = double(tree->visibility.pixel_count());
    std::cout << "\nK = " << k << ": " << format("%.0f%%", 100.0 * double(count(1.0f)) / pixels)
              << " of the pixels fully lit, "
              << format("%.0f%%", 100.0 * double(count(0.0f)) / pixels) << " fully shadowed\n";
  }
  return {};
}

}  // namespace
}  // namespace penumbra

int main(int argc, char** argv) {
  CLI::App app{"penumbra_bench_minmax: minmax_pcf's min-max traversal against brute force"};
  int repeats = 5;
  std::string device;
  app.add_option("-r,--repeats", repeats,
                 "Timed runs per variant, after an untimed one (the median GPU time is shown)")
      ->check(CLI::Range(3, 1000));
  app.add_option("--device", device, "Vulkan device: index or name substring");
  CLI11_PARSE(app, argc, argv);
  if (penumbra::Status status = penumbra::run(device, repeats); !status) {
    std::cerr << "penumbra_bench_minmax: error: " << status.error().to_string() << "\n";
    return 2;
  }
  return 0;
}
