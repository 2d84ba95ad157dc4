// Texel addressing follows docs/shader-interface.md: texel i covers u in [i/W, (i+1)/W),
// its centre is at (i + 0.5) / W, and reads outside the map clamp to the edge.
#include "penumbra/reference/sampling.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra::reference {
namespace {

int texel_index(double coord, int size) {
  // Clamp in double first: coordinates far outside the map must not overflow int.
  const double index = std::clamp(std::floor(coord), 0.0, double(size - 1));
  return int(index);
}

// The texel indices along one axis a point sample at `coord` (in texels) may
// read: the nearest first, then the neighbour across a boundary within `window`.
struct AxisCandidates {
  std::array<int, 2> index;
  int count;
};

AxisCandidates axis_candidates(double coord, int size, double window) {
  // Most samples sit inside a texel, away from its edges: floor(coord -
  // window) and floor(coord + window) are then floor(coord), which the same
  // two sums show without computing them.
  const double texel = std::floor(coord);
  if (coord - window >= texel && coord + window < texel + 1.0 && texel >= 0.0 &&
      texel < double(size)) {
    return {{int(texel), int(texel)}, 1};
  }
  const int nearest = texel_index(coord, size);
  const int low = texel_index(coord - window, size);
  const int high = texel_index(coord + window, size);
  if (low != nearest) return {{nearest, low}, 2};
  if (high != nearest) return {{nearest, high}, 2};
  return {{nearest, nearest}, 1};
}

}  // namespace

TexelCandidates candidate_texels(const ShadowMapView& map, double u, double v, double window) {
  const AxisCandidates columns = axis_candidates(u * map.width(), map.width(), window);
  const AxisCandidates rows = axis_candidates(v * map.height(), map.height(), window);
  TexelCandidates result;
  for (int b = 0; b < rows.count; ++b) {
    for (int a = 0; a < columns.count; ++a) {
      result.texels[result.count++] = {columns.index[a], rows.index[b]};
    }
  }
  return result;
}

double bilinear_compare(const ShadowMapView& map, double u, double v, double z_ref) {
  // Texel centres sit at half-integers, so the four texels around (u, v) start
  // at floor(u W - 0.5); the fractions are the weights of the second column/row.
  const double x = u * map.width() - 0.5;
  const double y = v * map.height() - 0.5;
  const double fx = std::floor(x);
  const double fy = std::floor(y);
  const double a = x - fx;
  const double b = y - fy;
  // Far outside the map every texel clamps to the edge; keep the indices in int range.
  const int i0 = int(std::clamp(fx, -1.0, double(map.width())));
  const int j0 = int(std::clamp(fy, -1.0, double(map.height())));
  // Clamp to the edge once per row and column, not once per texel.
  const int c0 = std::clamp(i0, 0, map.width() - 1), c1 = std::clamp(i0 + 1, 0, map.width() - 1);
  const double* r0 = map.row(std::clamp(j0, 0, map.height() - 1));
  const double* r1 = map.row(std::clamp(j0 + 1, 0, map.height() - 1));
  auto cmp = [&](const double* row, int i) { return lit(z_ref, row[i]) ? 1.0 : 0.0; };
  return (1 - a) * (1 - b) * cmp(r0, c0) + a * (1 - b) * cmp(r0, c1) + (1 - a) * b * cmp(r1, c0) +
         a * b * cmp(r1, c1);
}

}  // namespace penumbra::reference
