#include "penumbra/report/figures.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra::report {
namespace {

// Exact truth is computed in double: a fully lit or fully shadowed point
// gives 1 or 0 up to rounding of the union's area.
constexpr double kExactMargin = 1e-9;

bool in_penumbra(float exact) {
  return exact > kExactMargin && exact < 1.0 - kExactMargin;
}

// Mean, root mean square and max of |a - b|; a NaN counts as infinitely wrong.
struct Accumulator {
  double sum = 0.0, squares = 0.0, max = 0.0;
  std::size_t count = 0;

  void add(double a, double b) {
    const double e = std::abs(a - b);
    const double error = std::isnan(e) ? INFINITY : e;
    sum += error;
    squares += error * error;
    max = std::max(max, error);
    ++count;
  }
  double mean() const { return count ? sum / double(count) : 0.0; }
  double rms() const { return count ? std::sqrt(squares / double(count)) : 0.0; }
};

}  // namespace

Region region(const reference::StageView& view, const FloatImage& exact) {
  Region r;
  for (std::size_t i = 0; i < view.surfaces.size(); ++i) {
    if (!reference::receives_light(view.surfaces[i])) continue;
    ++r.measured;
    if (in_penumbra(exact.data[i])) ++r.penumbra;
  }
  return r;
}

Figures measure(const reference::StageView& view, const FloatImage& exact,
                const FloatImage& visibility, const FloatImage& reference,
                const FloatImage& reference_ambiguous, const FloatImage& texel_reads) {
  Accumulator penumbra, all, against_reference, reads;
  for (std::size_t i = 0; i < view.surfaces.size(); ++i) {
    if (!reference::receives_light(view.surfaces[i])) continue;
    const double v = visibility.data[i];
    if (in_penumbra(exact.data[i])) penumbra.add(v, exact.data[i]);
    all.add(v, exact.data[i]);
    if (reference_ambiguous.data[i] == 0.0f) against_reference.add(v, reference.data[i]);
    reads.add(texel_reads.data[i], 0.0);
  }
  return {penumbra.mean(),          penumbra.rms(),        penumbra.max, all.rms(), all.max,
          against_reference.mean(), against_reference.max, reads.mean(), reads.max};
}

nlohmann::json to_json(const Figures& f) {
  return {{"exact_penumbra_mae", f.exact_penumbra_mae},
          {"exact_penumbra_rmse", f.exact_penumbra_rmse},
          {"exact_penumbra_max", f.exact_penumbra_max},
          {"exact_rmse", f.exact_rmse},
          {"exact_max", f.exact_max},
          {"reference_mae", f.reference_mae},
          {"reference_max", f.reference_max},
          {"texel_reads_per_pixel", f.texel_reads_per_pixel},
          {"texel_reads_max", f.texel_reads_max}};
}

}  // namespace penumbra::report
