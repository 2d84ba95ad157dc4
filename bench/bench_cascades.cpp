// penumbra_bench_cascades: the CPU reference of cascaded variants on the
// cascaded stage (reference/cascades.hpp, docs/accuracy.md "Cascades"): per
// cascade, the penumbra error against the exact directional light; per
// boundary, the jump the picture would show there without blending (each
// band pixel evaluated in both cascades). The reference is what verify
// holds the shaders to, so these are what the shaders give.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "bench_files.hpp"
#include "penumbra/compiler/manifest.hpp"
#include "penumbra/reference/cascaded_view.hpp"
#include "penumbra/reference/exact_visibility.hpp"

namespace penumbra {
namespace {

bool reads_map_alone(Technique t) {
  return t == Technique::hard || t == Technique::pcf_grid || t == Technique::pcf_poisson ||
         t == Technique::pcss;
}

struct Mean {
  std::size_t count = 0;
  double sum = 0.0;
  void add(double x) {
    ++count;
    sum += x;
  }
  double value() const { return count ? sum / double(count) : 0.0; }
};

Status run(const std::string& manifest, const std::vector<std::string>& names) {
  PENUMBRA_TRY_ASSIGN(std::vector<Variant> variants, load_variants(manifest));
  const reference::CascadedStage stage = reference::cascaded_stage();
  const reference::Scene& scene = stage.stage.scene;
  const reference::StageView view =
      // Twice verify's picture each way: finer figures for the same stage.
      reference::view(stage.stage, 2 * scene.receivers_width, 2 * scene.receivers_height);
  const FloatImage exact = reference::exact_visibility_image(scene, view);
  const std::vector<reference::CascadeMap> maps = reference::cascade_maps(stage);
  const std::vector<reference::CascadeMap> uv_sized = reference::sized_as_nearest(stage, maps);
  std::vector<bool> penumbra(view.surfaces.size());
  for (std::size_t i = 0; i < penumbra.size(); ++i) {
    penumbra[i] =
        reference::receives_light(view.surfaces[i]) && exact.data[i] > 0.0f && exact.data[i] < 1.0f;
  }
  std::printf("cascades (view depth end, map side):");
  for (const reference::Cascade& c : stage.cascades)
    std::printf(" %.2f/%.2f", c.split_far, c.width);
  std::printf("\n%-40s %-38s %-30s %s\n", "variant", "penumbra MAE per cascade (pixels)",
              "seam jump: mean (pixels)", "sized in uv");
  for (const Variant& variant : variants) {
    const bool asked = names.empty() || std::ranges::find(names, variant.name) != names.end();
    // The reference reads linear depth: each encoding's twin gives the same.
    if (!asked || !reads_map_alone(variant.technique) || variant.keys.map_layout ||
        variant.keys.map_encoding) {
      continue;
    }
    PENUMBRA_TRY_ASSIGN(reference::CascadedImage image,
                        reference::evaluate_cascaded(variant, stage, view, maps));
    PENUMBRA_TRY_ASSIGN(reference::CascadedImage control,
                        reference::evaluate_cascaded(variant, stage, view, uv_sized));
    std::vector<Mean> errors(stage.cascades.size());
    for (std::size_t i = 0; i < penumbra.size(); ++i) {
      const int c = image.choices[i].first;
      if (penumbra[i] && c >= 0) {
        errors[std::size_t(c)].add(std::abs(image.visibility.data[i] - exact.data[i]));
      }
    }
    std::string per_cascade, per_seam, per_control;
    char text[64];
    for (const Mean& e : errors) {
      std::snprintf(text, sizeof text, "%.4f (%zu) ", e.value(), e.count);
      per_cascade += text;
    }
    for (const reference::SeamFigures& s : reference::seam_jumps(image, penumbra)) {
      std::snprintf(text, sizeof text, "%.4f (%zu) ", s.mean, s.pixels);
      per_seam += text;
    }
    for (const reference::SeamFigures& s : reference::seam_jumps(control, penumbra)) {
      std::snprintf(text, sizeof text, "%.4f ", s.mean);
      per_control += text;
    }
    std::printf("%-40s %-38s %-30s %s\n", variant.name.c_str(), per_cascade.c_str(),
                per_seam.c_str(), per_control.c_str());
  }
  return {};
}

}  // namespace
}  // namespace penumbra

int main(int argc, char** argv) {
  CLI::App app{"penumbra_bench_cascades: cascaded variants' reference on the cascaded stage"};
  std::string manifest;
  std::vector<std::string> names;
  app.add_option("--manifest", manifest,
                 "Manifest whose hard, pcf_grid, pcf_poisson and pcss variants are measured "
                 "(default: the shipped default.json)");
  app.add_option("--variant", names, "Only these variants (repeatable)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::cerr << "penumbra_bench_cascades: " << e.what() << "\n";
    return 2;
  }
  if (manifest.empty()) {
    auto shipped = penumbra::bench::default_manifest("default.json");
    if (!shipped) {
      std::cerr << "penumbra_bench_cascades: " << shipped.error().to_string() << "\n";
      return 2;
    }
    manifest = shipped->string();
  }
  const penumbra::Status status = penumbra::run(manifest, names);
  if (!status) {
    std::cerr << "penumbra_bench_cascades: " << status.error().to_string() << "\n";
    return 2;
  }
  return 0;
}
