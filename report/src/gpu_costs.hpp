// The report's GPU costs: every wanted variant's spirv passes on the stage,
// timed as penumbra_bench_gpu times them (measure_gpu_cost: timestamp
// queries, median of runs), with the error of the same run.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "cost_chart.hpp"
#include "penumbra/reference/stage.hpp"
#include "penumbra/verify/gpu_cost.hpp"

namespace penumbra::report {

struct TimedVariant {
  GpuCost cost;
  CostPoint point;  // what the chart plots
};

// The variants of `pictures` (its variants and targets filters: none when
// spirv is not wanted) with spirv, in library order. A variant that cannot
// be timed is left out with a warning diagnostic naming why.
std::vector<TimedVariant> time_variants(const Library& library, Engine& engine,
                                        const PictureScene& scene, const reference::StageView& view,
                                        const FloatImage& exact, const PictureOptions& pictures,
                                        const GpuCostOptions& options,
                                        const DiagnosticConsumer& diagnostics);

// report.json's "gpu_cost": the method and each variant's times and figures.
nlohmann::json to_json(const std::vector<TimedVariant>& timed, const GpuCostOptions& options);

}  // namespace penumbra::report
