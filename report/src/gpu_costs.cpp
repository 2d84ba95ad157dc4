#include "gpu_costs.hpp"

#include <algorithm>

#include "penumbra/report/figures.hpp"

namespace penumbra::report {

std::vector<TimedVariant> time_variants(const Library& library, Engine& engine,
                                        const PictureScene& scene, const reference::StageView& view,
                                        const FloatImage& exact, const PictureOptions& pictures,
                                        const GpuCostOptions& options,
                                        const DiagnosticConsumer& diagnostics) {
  std::vector<TimedVariant> timed;
  const auto listed = [](const auto& list, const auto& item) {
    return list.empty() || std::find(list.begin(), list.end(), item) != list.end();
  };
  if (!listed(pictures.targets, Target::spirv)) return timed;
  for (const LibraryVariant& entry : library.variants) {
    const Variant& variant = entry.variant;
    if (!listed(pictures.variants, variant.name) ||
        std::find(variant.targets.begin(), variant.targets.end(), Target::spirv) ==
            variant.targets.end()) {
      continue;
    }
    std::string reason = off_stage(variant);
    if (reason.empty()) reason = form_not_built(variant, Form::query);
    if (!reason.empty()) {
      diagnostics({Severity::note, variant.name, "not timed for the cost chart: " + reason});
      continue;
    }
    auto cost = measure_gpu_cost(library, engine, entry, scene, options);
    if (!cost) {
      diagnostics({Severity::warning, variant.name,
                   "not timed for the cost chart: " + cost.error().to_string()});
      continue;
    }
    // The run's own error: the image stands in for the CPU reference,
    // whose figures the chart does not use.
    const FloatImage none(cost->visibility.width, cost->visibility.height, 1);
    const Figures f =
        measure(view, exact, cost->visibility, cost->visibility, none, cost->texel_reads);
    CostPoint point{variant.name, std::string(to_string(variant.technique)), cost->total_ms(),
                    f.texel_reads_per_pixel, f.exact_penumbra_mae};
    timed.push_back({std::move(*cost), std::move(point)});
    timed.back().cost.visibility = timed.back().cost.texel_reads = FloatImage();
  }
  return timed;
}

nlohmann::json to_json(const std::vector<TimedVariant>& timed, const GpuCostOptions& options) {
  nlohmann::json variants = nlohmann::json::array();
  for (const TimedVariant& t : timed) {
    variants.push_back({{"variant", t.point.variant},
                        {"technique", t.point.technique},
                        {"target", "spirv"},
                        {"path", "vulkan"},
                        {"gpu_ms", t.point.gpu_ms},
                        {"depth_ms", t.cost.depth_ms},
                        {"mip_ms", t.cost.mip_ms},
                        {"query_ms", t.cost.query_ms},
                        {"texel_reads_per_pixel", t.point.texel_reads},
                        {"exact_penumbra_mae", t.point.mae}});
  }
  return {{"method", "median GPU time of " + std::to_string(options.runs) +
                         " runs of each pass after an untimed one, from Vulkan timestamp queries "
                         "(penumbra_bench_gpu's method); gpu_ms = depth_ms + mip_ms + query_ms"},
          {"runs", options.runs},
          {"chart_image", "cost_chart.png"},
          {"variants", variants}};
}

}  // namespace penumbra::report
