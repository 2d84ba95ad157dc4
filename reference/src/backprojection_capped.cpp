// backprojection where a target caps its walk (hlsl_dx9): the shader's walk
// step for step (backprojection_walk.hpp), since the area then depends on
// which nodes the walk reached and which it finished coarse. Nodes are
// projected whole, as the shader does; the decisions that steer the walk are
// the shader's exact float compares, except whether a node can touch the
// light, which the shader tests in float32 and the reference in double: one
// too close to call marks the receiver ambiguous.
#include "backprojection_walk.hpp"
#include "penumbra/reference/backprojection.hpp"
#include "technique_parts.hpp"

namespace penumbra::reference::detail {
namespace {

// Whether coordinate `uv` of the window's edges lies so close to a texel
// boundary that the shader's float32 floor may fall on the other side.
bool edge_close(double uv, int size) {
  const double texels = uv * size;
  return std::abs(texels - std::round(texels)) <= 1e-5;
}

}  // namespace

bool window_edges_close(const ShadowMapView& map, const MinMaxMip& mip, const LightParams& light,
                        const Query& q) {
  const double nearest = mip.node(mip.top_level(), 0, 0).min;
  const double reach = backprojection_reach(light, q, nearest);
  bool close = false;
  for (double sign : {-1.0, 1.0}) {
    close = close || edge_close(q.u + sign * reach, map.width()) ||
            edge_close(q.v + sign * reach, map.height());
  }
  return close;
}

Sample backprojection_capped(const ShadowMapView& map, const MinMaxMip& mip,
                             const LightParams& light, const Query& q, const TexelRect& window,
                             const VariantKeys& keys, int steps) {
  const Projector projector(map, light, q);
  const double whole = 4.0 * projector.half() * projector.half();
  const float limit = occluder_limit(light, q);
  double area = 0.0, error = 0.0;
  auto add = [&](const TexelRect& texels, double z, double share) {
    const PlaneRect r = projector.project(texels, z);
    area += share * overlap(r.x0, r.x1, projector.half()) * overlap(r.y0, r.y1, projector.half());
    error += share * projector.area_error(r, z);
  };
  // The min-max walk finishes coarse: a node it cannot refine counts as one
  // patch at its min depth, whole where every texel occludes and half where
  // some may not (docs/targets.md has the bound). Brute force stops.
  const WalkEnd end = walk_backprojection(
      map, mip, projector, limit, window, keys, steps,
      [&](const TexelRect& texels, double z) { add(texels, z, 1.0); },
      [&] { return area >= whole; },
      [&](const TexelRect& texels, MinMax range) {
        add(texels, double(range.min), range.max < limit ? 1.0 : 0.5);
      });
  // A decision too close to call changes the result only through the steps
  // it costs, so only where the steps ran short.
  const bool close = end.close || window_edges_close(map, mip, light, q);
  // The patches' edges, as in the uncapped walk (area_edges_close()).
  return {backprojection_visibility(area, light),
          ambiguous_if(close && (end.truncated || end.coarse), Ambiguity::walk_decision) |
              ambiguous_if(error > kBackprojectionEdgeBudget * whole, Ambiguity::area_edges)};
}

}  // namespace penumbra::reference::detail
