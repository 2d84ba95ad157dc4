// backprojection's reference: brute force over the texels that can matter.
// In slopes a = (u - 0.5) Fw / n, a patch at depth z projects from the
// receiver (slope a_r, depth z_r) to X = (a - a_r) g(z), g(z) = z z_r / (z_r - z)
// (a directional light's: backprojection.hpp). g grows with z, so a texel whose nearest slope edge
// is farther than L / g(zlo) from a_r misses the light for every depth >= zlo: with zlo the map's
// minimum, the texels outside backprojection_window() add exactly 0. Texels at or behind the
// receiver (possible only with a negative bias) cannot be projected towards the light and add
// nothing.
#include "penumbra/reference/backprojection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "backprojection_walk.hpp"
#include "penumbra/reference/sampling.hpp"
#include "technique_parts.hpp"

namespace penumbra::reference {
namespace {

// The texel index containing uv coordinate `coord`, held within a texel of
// the map so that it stays in int range.
int texel_floor(double coord, int size) {
  return int(std::clamp(std::floor(coord * size), -1.0, double(size)));
}

}  // namespace

double backprojection_to_slope(const LightParams& light) {
  return light.orthographic() ? light.frustum_width : light.frustum_width / light.near_plane;
}

double backprojection_gain(const LightParams& light, double z, double z_receiver) {
  return light.orthographic() ? 1.0 / (z_receiver - z) : z * z_receiver / (z_receiver - z);
}

double backprojection_reach(const LightParams& light, const Query& q, double min_depth) {
  return light.orthographic()
             ? light.light_size_uv() * (q.z - min_depth)
             : light.light_size_uv() * light.near_plane * (q.z - min_depth) / (q.z * min_depth);
}

double detail::overlap(double lo, double hi, double half) {
  return std::max(0.0, std::min(hi, half) - std::max(lo, -half));
}

TexelRect backprojection_window(const ShadowMapView& map, const LightParams& light, const Query& q,
                                double min_depth) {
  if (min_depth >= q.z) return {};
  const TexelRect whole{0, 0, map.width() - 1, map.height() - 1};
  if (min_depth <= 0.0 && !light.orthographic()) return whole;
  const double reach = backprojection_reach(light, q, min_depth);
  const TexelRect window{
      texel_floor(q.u - reach, map.width()) - 1, texel_floor(q.v - reach, map.height()) - 1,
      texel_floor(q.u + reach, map.width()) + 1, texel_floor(q.v + reach, map.height()) + 1};
  return clip(window, map.width(), map.height());
}

double backprojected_area(const ShadowMapView& map, const LightParams& light, const Query& q,
                          const TexelRect& texels) {
  const TexelRect inside = clip(texels, map.width(), map.height());
  if (inside.empty()) return 0.0;
  const float z_ref = float_reference(q.z, light.bias);
  const double to_slope = backprojection_to_slope(light);
  const double L = light.light_world_size;
  const double a_r = (q.u - 0.5) * to_slope;
  const double b_r = (q.v - 0.5) * to_slope;
  // Column i spans slopes edges[i - x0] to edges[i - x0 + 1], computed
  // once per column rather than once per texel: the same values.
  thread_local std::vector<double> edges;
  edges.resize(std::size_t(inside.x1 - inside.x0 + 2));
  for (int i = inside.x0; i <= inside.x1 + 1; ++i) {
    edges[std::size_t(i - inside.x0)] = (double(i) / map.width() - 0.5) * to_slope - a_r;
  }
  double area = 0.0;
  for (int j = inside.y0; j <= inside.y1; ++j) {
    const double b0 = (double(j) / map.height() - 0.5) * to_slope - b_r;
    const double b1 = (double(j + 1) / map.height() - 0.5) * to_slope - b_r;
    const double* depths = map.row(j);
    for (int i = inside.x0; i <= inside.x1; ++i) {
      const double z = depths[i];
      if (!(float(z) < z_ref) || z >= q.z) continue;
      const double g = backprojection_gain(light, z, q.z);
      const double a0 = edges[std::size_t(i - inside.x0)];
      const double a1 = edges[std::size_t(i - inside.x0 + 1)];
      area += detail::overlap(a0 * g, a1 * g, L) * detail::overlap(b0 * g, b1 * g, L);
    }
  }
  return area;
}

double backprojection_visibility(double area, const LightParams& light) {
  const double side = 2.0 * light.light_world_size;
  return std::max(0.0, 1.0 - area / (side * side));
}

namespace detail {

bool area_edges_close(const ShadowMapView& map, const MinMaxMip& mip, const LightParams& light,
                      const Query& q, const TexelRect& window, const VariantKeys& keys, int steps) {
  const Projector projector(map, light, q);
  const double whole = 4.0 * projector.half() * projector.half();
  double area = 0.0, error = 0.0;
  walk_backprojection(
      map, mip, projector, occluder_limit(light, q), window, keys, steps,
      [&](const TexelRect& texels, double z) {
        const PlaneRect r = projector.project(texels, z);
        area += overlap(r.x0, r.x1, projector.half()) * overlap(r.y0, r.y1, projector.half());
        error += projector.area_error(r, z);
      },
      [&] { return area >= whole; });
  return error > kBackprojectionEdgeBudget * whole;
}

Sample backprojection(const ShadowMapView& map, const MinMaxMip& mip, const LightParams& light,
                      const Query& q, const VariantKeys& keys, std::optional<int> capped_steps) {
  const MinMax top = mip.node(mip.top_level(), 0, 0);
  if (!(top.min < float_reference(q.z, light.bias))) return {1.0};
  const TexelRect window = backprojection_window(map, light, q, top.min);
  if (capped_steps && !window.empty()) {
    return backprojection_capped(map, mip, light, q, window, keys, *capped_steps);
  }
  // The GPU's walk hands over flat nodes: their edges, not the texels', are
  // the ones float32 may move.
  const bool close = !window.empty() && area_edges_close(map, mip, light, q, window, keys,
                                                         std::numeric_limits<int>::max());
  return {backprojection_visibility(backprojected_area(map, light, q, window), light),
          ambiguous_if(close, Ambiguity::area_edges)};
}

}  // namespace detail
}  // namespace penumbra::reference
