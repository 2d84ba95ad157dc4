// bitmask_backprojection's reference ("Bitmask Soft Shadows", Schwarz &
// Stamminger 2007): the shader's walk, setting the bits of the light
// samples each patch covers; sample (c, r) of the G x G bits lies at
// (c G + r + 0.5, r G + c + 0.5) / N of the light's side (the Hammersley set
// in base G). A sample lies in a patch when it is within the patch's edges
// on both axes; the shader decides that in float32, so where a sample lies
// within an edge's float error its bit is undecided, and a receiver with an
// undecided bit that no other patch surely sets is ambiguous. The shader
// widens every patch by BITMASK_EDGE_MARGIN (kEdgeMargin): an edge two
// patches share is computed in the x0/y0 lane of one and the x1/y1 lane of
// the other, which a compiler may evaluate differently where nothing is
// `precise`, and overlapped by twice the margin one of them surely covers
// a sample near it wherever its error is below the margin.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "backprojection_walk.hpp"
#include "penumbra/reference/backprojection.hpp"
#include "technique_parts.hpp"

namespace penumbra::reference::detail {
namespace {

// The shader's BITMASK_EDGE_MARGIN, in units of 1 / N of the light's side.
constexpr double kEdgeMargin = 0.0625;

class LightSamples {
 public:
  LightSamples(int side, double half)
      : side_(side), half_(half), sure_(std::size_t(side), 0u), maybe_(std::size_t(side), 0u) {}

  // Sets the bits of the samples inside `r`, a patch at depth z.
  void cover(const PlaneRect& r, const Projector& projector, double z) {
    // Edges in units of 1 / N of the light's side, less half a unit, and
    // their float error in those units: the edge's, and 1e-6 relative for
    // (X + L) N / (2L) - 0.5 and the shader's division by G (about 13 ulp
    // of a 2.5-ulp quotient, an fma or not).
    const double scale = double(side_) * side_ / (2.0 * half_);
    auto unit = [&](double edge) { return (edge + half_) * scale - 0.5; };
    auto error = [&](double edge, int axis) {
      return projector.edge_error(edge, z, axis) * scale + 1e-6 * (std::abs(unit(edge)) + 1.0);
    };
    const double e[4] = {error(r.x0, 0), error(r.y0, 1), error(r.x1, 0), error(r.y1, 1)};
    const double t[4] = {unit(r.x0) - kEdgeMargin, unit(r.y0) - kEdgeMargin,
                         unit(r.x1) + kEdgeMargin, unit(r.y1) + kEdgeMargin};
    const double maybe[4] = {t[0] - e[0], t[1] - e[1], t[2] + e[2], t[3] + e[3]};
    const double sure[4] = {t[0] + e[0], t[1] + e[1], t[2] - e[2], t[3] - e[3]};
    // Row r's samples lie at y in [r G, r G + G - 1]: rows a whole row
    // below or above the patch's widest edges hold none of them.
    int first = 0, last = side_ - 1;
    if (std::isfinite(maybe[1]) && std::isfinite(maybe[3])) {
      const double g = side_;
      first = int(std::clamp(std::floor((maybe[1] - g + 1.0) / g) - 1.0, 0.0, g));
      last = int(std::clamp(std::floor(maybe[3] / g) + 1.0, -1.0, g - 1.0));
    }
    for (int row = first; row <= last; ++row) {
      maybe_[std::size_t(row)] |= row_mask(maybe, row);
      // Counted as they are set, as the shader's state.set: covered() asks
      // after every step of the walk.
      const std::uint32_t fresh = row_mask(sure, row) & ~sure_[std::size_t(row)];
      sure_[std::size_t(row)] |= fresh;
      set_ += std::popcount(fresh);
    }
  }
  int set() const { return set_; }
  bool full() const { return set_ == side_ * side_; }
  // Some bit may be set by the shader that the reference leaves clear.
  bool undecided() const {
    for (std::size_t row = 0; row < sure_.size(); ++row) {
      if (maybe_[row] & ~sure_[row]) return true;
    }
    return false;
  }

 private:
  // The bits of row `row` whose samples (c G + row, row G + c) lie in the
  // rectangle `t` (x0, y0, x1, y1) of sample units.
  std::uint32_t row_mask(const double (&t)[4], int row) const {
    const double g = side_;
    const double first = std::max(std::ceil((t[0] - row) / g), std::ceil(t[1] - row * g));
    const double last = std::min(std::floor((t[2] - row) / g), std::floor(t[3] - row * g));
    const int lo = int(std::clamp(first, 0.0, g));
    const int hi = int(std::clamp(last, -1.0, g - 1.0));
    if (lo > hi) return 0u;
    return std::uint32_t((std::uint64_t{2} << hi) - (std::uint64_t{1} << lo));
  }

  int side_;
  double half_;
  std::vector<std::uint32_t> sure_;
  std::vector<std::uint32_t> maybe_;
  int set_ = 0;  // bits of sure_ set
};

}  // namespace

Sample bitmask_backprojection(const ShadowMapView& map, const MinMaxMip& mip,
                              const LightParams& light, const Query& q, const VariantKeys& keys,
                              int steps) {
  const MinMax top = mip.node(mip.top_level(), 0, 0);
  const float limit = occluder_limit(light, q);
  if (!(top.min < limit)) return {1.0};
  const TexelRect window = backprojection_window(map, light, q, top.min);
  if (window.empty()) return {1.0};
  const Projector projector(map, light, q);
  const int side = light_grid_side(keys.light_bits.value());
  LightSamples samples(side, light.light_world_size);
  const WalkEnd end = walk_backprojection(
      map, mip, projector, limit, window, keys, steps,
      [&](const TexelRect& texels, double z) {
        samples.cover(projector.project(texels, z), projector, z);
      },
      [&] { return samples.full(); });
  // A walk stopped short by its bound may not reach the patch that would
  // surely cover a sample, and where it stops depends on decisions too
  // close to call.
  return {1.0 - double(samples.set()) / (side * side),
          ambiguous_if(samples.undecided(), Ambiguity::light_sample_edge) |
              ambiguous_if(end.truncated, Ambiguity::walk_truncated)};
}

}  // namespace penumbra::reference::detail
