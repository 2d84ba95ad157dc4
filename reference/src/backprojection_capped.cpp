// backprojection where a target caps its walk (hlsl_dx9): the shader's walk
// step for step (shaderlib/techniques/backprojection.glsl), since the area
// then depends on which nodes the walk reached. Nodes are projected whole,
// as the shader does; the decisions that steer the walk are the shader's
// exact float compares, except whether a node can touch the light, which
// the shader tests in float32 and the reference in double: one too close
// to call marks the receiver ambiguous.
#include <algorithm>
#include <cmath>

#include "penumbra/reference/backprojection.hpp"
#include "penumbra/reference/minmax_cursor.hpp"
#include "penumbra/reference/sampling.hpp"
#include "technique_parts.hpp"

namespace penumbra::reference::detail {
namespace {

// A light-plane rectangle (X0, Y0, X1, Y1).
struct PlaneRect {
  double x0, y0, x1, y1;
};

class Projector {
 public:
  Projector(const ShadowMapView& map, const LightParams& light, const Query& q)
      : map_(map),
        q_(q),
        to_slope_(light.frustum_width / light.near_plane),
        half_(light.light_world_size) {}

  // The patch of `texels` at linear depth z projected from the receiver.
  PlaneRect project(const TexelRect& texels, double z) const {
    const double gain = z * q_.z / (q_.z - z);
    auto slope = [&](int texel, int size, double receiver) {
      return ((double(texel) / size - 0.5) - (receiver - 0.5)) * to_slope_ * gain;
    };
    return {slope(texels.x0, map_.width(), q_.u), slope(texels.y0, map_.height(), q_.v),
            slope(texels.x1 + 1, map_.width(), q_.u), slope(texels.y1 + 1, map_.height(), q_.v)};
  }
  // Its area inside the light [-L, L]^2.
  double light_area(const PlaneRect& r) const {
    return overlap(r.x0, r.x1, half_) * overlap(r.y0, r.y1, half_);
  }
  // Whether it reaches the light, and whether float32 might say otherwise.
  bool touches(const PlaneRect& r, bool& close) const {
    auto near = [&](double edge, double bound) {
      return std::abs(edge - bound) <= 1e-6 * (std::abs(edge) + half_);
    };
    close =
        close || near(r.x0, half_) || near(r.y0, half_) || near(r.x1, -half_) || near(r.y1, -half_);
    return r.x0 <= half_ && r.y0 <= half_ && r.x1 >= -half_ && r.y1 >= -half_;
  }
  double whole_light() const { return 4.0 * half_ * half_; }

 private:
  const ShadowMapView& map_;
  const Query& q_;
  double to_slope_;
  double half_;
};

// Whether coordinate `uv` of the window's edges lies so close to a texel
// boundary that the shader's float32 floor may fall on the other side.
bool edge_close(double uv, int size) {
  const double texels = uv * size;
  return std::abs(texels - std::round(texels)) <= 1e-5;
}

}  // namespace

Sample backprojection_capped(const ShadowMapView& map, const MinMaxMip& mip,
                             const LightParams& light, const Query& q, const TexelRect& window,
                             const VariantKeys& keys, int steps) {
  const Projector projector(map, light, q);
  // Occluding (below the biased reference) and in front of the receiver.
  const float limit = std::min(float_reference(q.z, light.bias), float(q.z));
  const int max_nodes = keys.max_nodes.value_or(kDefaultMaxNodes);
  const double whole = projector.whole_light();
  double area = 0.0;
  bool close = false;
  bool truncated = false;  // stopped by the cap, not by the walk's own ends
  if (keys.traversal == kBruteForceTraversal) {
    const long long texels = std::min<long long>(window.count(), std::min(steps, max_nodes));
    truncated = steps < std::min<long long>(window.count(), max_nodes);
    for (long long n = 0; n < texels; ++n) {
      const int i = window.x0 + int(n % (window.x1 - window.x0 + 1));
      const int j = window.y0 + int(n / (window.x1 - window.x0 + 1));
      const float depth = float(map.depth(i, j));
      if (depth < limit) area += projector.light_area(projector.project({i, j, i, j}, depth));
    }
  } else {
    MinmaxCursor cursor(window);
    int visits = 0;
    bool done = false;
    for (int step = 0; step < steps && !done; ++step) {
      bool descend = false;
      if (!cursor.climbed()) ++visits;
      if (!cursor.climbed() && !intersect(cursor.texels(), window).empty()) {
        const MinMax range = mip.node(cursor.level(), cursor.x(), cursor.y());
        const TexelRect texels = clip(cursor.texels(), map.width(), map.height());
        if (range.min < limit && projector.touches(projector.project(texels, range.min), close)) {
          if (range.max < limit && range.min == range.max) {
            area += projector.light_area(projector.project(texels, range.min));
          } else {
            descend = cursor.level() > 0;
          }
        }
      }
      if (descend) {
        cursor.descend();
      } else {
        cursor.next();
      }
      done = cursor.done() || area >= whole || visits >= max_nodes;
    }
    truncated = !done;
  }
  // The window's edges (backprojection_window()).
  const double nearest = mip.node(mip.top_level(), 0, 0).min;
  const double reach = light.light_size_uv() * light.near_plane * (q.z - nearest) / (q.z * nearest);
  for (double sign : {-1.0, 1.0}) {
    close = close || edge_close(q.u + sign * reach, map.width()) ||
            edge_close(q.v + sign * reach, map.height());
  }
  // A decision too close to call changes the result only through the steps
  // it costs, so only where the cap stopped the walk.
  return {backprojection_visibility(area, light), close && truncated};
}

}  // namespace penumbra::reference::detail
