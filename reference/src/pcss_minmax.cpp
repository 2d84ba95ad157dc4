// pcss_minmax's reference: PCSS whose blocker search reads the <= 3 x 3
// min-max nodes covering the search window instead of point samples: the
// blocker depth is the mean of the blocking nodes' minima, each weighted by
// the window texels in its node. The window's edges are formed
// in float like the GPU; an edge within a quantization step of a texel
// boundary may land on either side on a GPU, so when the other choice would
// change the blocker depth the pixel is ambiguous. The filtering step is
// pcss's, shared through poisson_pcf(). Blocker depths below the near plane
// (only a hand-made map holds them) are taken as the near plane, as the
// shader does, so the penumbra stays finite.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "penumbra/reference/sampling.hpp"
#include "technique_parts.hpp"

namespace penumbra::reference::detail {
namespace {

// The texel indices a GPU may give floor(edge): floor(edge) first, then the
// neighbour across an integer within `window`. Held in int range.
struct EdgeChoices {
  std::array<int, 2> index;
  int count;
};

// floor(x), held at +-2^24 far outside any map so that it stays in int range.
int floor_index(double x) {
  constexpr double kFar = 16777216.0;
  return int(std::clamp(std::floor(x), -kFar, kFar));
}

EdgeChoices edge_choices(float edge, double window) {
  const int nearest = floor_index(edge);
  const int low = floor_index(edge - window);
  const int high = floor_index(edge + window);
  if (low != nearest) return {{nearest, low}, 2};
  if (high != nearest) return {{nearest, high}, 2};
  return {{nearest, nearest}, 1};
}

// The blocker depth a window gives: over the nodes of the search level that
// meet it and whose minimum occludes, the minima weighted by the window
// texels each node holds.
std::optional<float> blocker_depth(const MinMaxMip& mip, const TexelRect& window, float z_ref) {
  const TexelRect inside = clip(window, mip.width(0), mip.height(0));
  if (inside.empty()) return std::nullopt;
  const int level = level_spanning(inside, 3);
  double depth_sum = 0.0;
  long long texels = 0;
  for (int j = inside.y0 >> level; j <= inside.y1 >> level; ++j) {
    for (int i = inside.x0 >> level; i <= inside.x1 >> level; ++i) {
      const float node_min = mip.node(level, i, j).min;
      if (!(node_min < z_ref)) continue;
      const long long weight = intersect(mip.extent(level, i, j), inside).count();
      depth_sum += double(node_min) * double(weight);
      texels += weight;
    }
  }
  if (texels == 0) return std::nullopt;
  return float(depth_sum / double(texels));
}

// Steps 2 and 3 for a blocker depth (none: lit): the parallel-plane
// penumbra, as pcss, with the blocker no nearer than the near plane (a
// rendered map holds nothing nearer, and a blocker at z = 0 would make the
// penumbra infinite), then pcss's filtering.
double filtered(const ShadowMapView& map, const LightParams& light, const Query& q,
                const Disk& pcf_disk, std::optional<float> z_b) {
  if (!z_b) return 1.0;
  const double blocker = std::max(double(*z_b), light.near_plane);
  return poisson_pcf(map, q, q.z - light.bias, pcf_disk.points,
                     pcss_filter_radius(light, q.z, blocker));
}

}  // namespace

Sample pcss_minmax(const ShadowMapView& map, const MinMaxMip& mip, const LightParams& light,
                   const Query& q, const Disk& pcf_disk, const SamplingPrecision& precision) {
  // Up to the near plane, lit, as pcss.
  if (!(q.z > light.near_plane)) return {1.0};
  // Step 1, blocker search over the window of uv half-width w around (u, v),
  // pcss's region, in float as the shader floors its edges.
  const float w = pcss_search_width(light, float(q.z));
  const float u = float(q.u), v = float(q.v);
  const float width = float(map.width()), height = float(map.height());
  const double window = precision.point_window();
  const EdgeChoices x0 = edge_choices((u - w) * width, window);
  const EdgeChoices x1 = edge_choices((u + w) * width, window);
  const EdgeChoices y0 = edge_choices((v - w) * height, window);
  const EdgeChoices y1 = edge_choices((v + w) * height, window);
  const float z_ref = float_reference(q.z, light.bias);
  const std::optional<float> z_b =
      blocker_depth(mip, {x0.index[0], y0.index[0], x1.index[0], y1.index[0]}, z_ref);
  const double visibility = filtered(map, light, q, pcf_disk, z_b);

  // A window edge that a GPU may round to the other texel changes the
  // weights: ambiguous only when that moves the result past the tolerance.
  const double allowed = tolerance(Technique::pcss_minmax, precision);
  bool ambiguous = false;
  for (int a = 0; a < x0.count; ++a) {
    for (int b = 0; b < x1.count; ++b) {
      for (int c = 0; c < y0.count; ++c) {
        for (int d = 0; d < y1.count; ++d) {
          const TexelRect other{x0.index[a], y0.index[c], x1.index[b], y1.index[d]};
          const std::optional<float> other_z_b = blocker_depth(mip, other, z_ref);
          if (ambiguous || other_z_b == z_b) continue;
          ambiguous = std::abs(filtered(map, light, q, pcf_disk, other_z_b) - visibility) > allowed;
        }
      }
    }
  }
  return {visibility, ambiguous_if(ambiguous, Ambiguity::search_window_edge)};
}

}  // namespace penumbra::reference::detail
