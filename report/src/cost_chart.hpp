// The report's cost chart (docs/verification.md, "Report"): each variant's
// exact_penumbra_mae against its GPU time (one panel) and against its texel
// reads per pixel (the other), the Pareto front of each panel marked and
// labelled, the points coloured by technique. Drawn as inline SVG for the
// page and rasterized here, with the same layout, as a PNG.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "png_file.hpp"

namespace penumbra::report {

struct CostPoint {
  std::string variant;
  std::string technique;
  double gpu_ms = 0.0;       // depth + min-max mip + query: median GPU times (timestamp queries)
  double texel_reads = 0.0;  // texel_reads_per_pixel over the measured pixels
  double mae = 0.0;          // exact_penumbra_mae
};

// What a panel plots against exact_penumbra_mae.
enum class CostAxis { gpu_ms, texel_reads };

double cost_of(const CostPoint& point, CostAxis axis);

// The points no other point beats (no more cost and no more error, and less
// of one), as indices ordered by cost; of equal points, the first.
std::vector<std::size_t> pareto_front(const std::vector<CostPoint>& points, CostAxis axis);

// <svg id="cost-chart">: one <g class="panel" data-axis="gpu_ms|texel_reads">
// per panel with one <circle class="point"> per point (class "point pareto"
// on the front, data-variant and data-technique on each), the front as
// <polyline class="pareto-front">, the front's points labelled by variant
// (<text class="point-label">), and a legend of the techniques
// (<text class="technique-label">).
std::string cost_chart_svg(const std::vector<CostPoint>& points);

// The same chart as a picture.
Picture cost_chart_picture(const std::vector<CostPoint>& points);

}  // namespace penumbra::report
