// The shaders' back-projection walk (shaderlib/common/backprojection_walk.glsl)
// step for step, shared by backprojection where a target caps it and by
// bitmask_backprojection: which patches a receiver's walk hands over, and
// whether one of its float32 decisions was too close to call.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "penumbra/model/light.hpp"
#include "penumbra/model/model.hpp"
#include "penumbra/reference/backprojection.hpp"
#include "penumbra/reference/minmax_cursor.hpp"
#include "penumbra/reference/sampling.hpp"
#include "penumbra/reference/techniques.hpp"

namespace penumbra::reference::detail {

// A light-plane rectangle (X0, Y0, X1, Y1).
struct PlaneRect {
  double x0, y0, x1, y1;
};

class Projector {
 public:
  Projector(const ShadowMapView& map, const LightParams& light, const Query& q)
      : map_(map),
        light_(light),
        q_(q),
        to_slope_(backprojection_to_slope(light)),
        half_(light.light_world_size) {}

  // g(z), from slope difference to light-plane distance (backprojection.hpp).
  double gain(double z) const { return backprojection_gain(light_, z, q_.z); }
  // The patch of `texels` at linear depth z projected from the receiver.
  PlaneRect project(const TexelRect& texels, double z) const {
    const double g = gain(z);
    auto slope = [&](int texel, int size, double receiver) {
      return ((double(texel) / size - 0.5) - (receiver - 0.5)) * to_slope_ * g;
    };
    return {slope(texels.x0, map_.width(), q_.u), slope(texels.y0, map_.height(), q_.v),
            slope(texels.x1 + 1, map_.width(), q_.u), slope(texels.y1 + 1, map_.height(), q_.v)};
  }
  // How far float32 may put an edge X = (c - c_r) s of a patch at depth z
  // along `axis` (0: X from u, 1: Y from v; c the texel corner's map
  // coordinate, c_r the receiver's, s = g(z) Fw / n), as the shader
  // computes it (backprojection_project()), under any evaluation GLSL
  // allows where nothing is `precise` (GLSL 3.30 and ESSL 3.00 have no
  // `precise`): a * b + c fused or not, the products of s regrouped, each
  // division within 2.5 ulp, and each site (the x0/y0 and x1/y1 lanes)
  // choosing for itself; no compiler distributes the product over the
  // difference (that adds an operation). With u = 2^-24, to first order: c
  // = t TS errs by 2u |c| (TS = 1 / size rounded, then the product), and
  // not at all where the size is a power of two; c - c_r by u |c - c_r|; s
  // relatively by 13u (g(z) 7u, Fw / n 5u, their product u); the last
  // product by u: u (2 s |c| + 15 |X|), the second term rounded up to 16u
  // for the higher orders. An edge two patches share is computed by both
  // lanes, so their values may differ by both errors.
  double edge_error(double edge, double z, int axis) const {
    constexpr double u = 0x1p-24;
    const int size = axis == 0 ? map_.width() : map_.height();
    const bool exact_corners = (size & (size - 1)) == 0;
    const double corner = exact_corners ? 0.0 : 2.0 * gain(z) * to_slope_;
    return u * (corner + 16.0 * std::abs(edge));
  }
  // How far float32 may move the area of `r` (a patch at depth z) inside
  // the light: each edge within its error of the light, moved by that
  // error, times the other axis's widest span inside the light.
  double area_error(const PlaneRect& r, double z) const {
    const double e[4] = {edge_error(r.x0, z, 0), edge_error(r.y0, z, 1), edge_error(r.x1, z, 0),
                         edge_error(r.y1, z, 1)};
    auto reach = [&](double edge, double error) {
      return std::abs(edge) < half_ + error ? error : 0.0;
    };
    auto span = [&](double lo, double hi) {
      return std::max(0.0, std::min(hi, half_) - std::max(lo, -half_));
    };
    const double x = span(r.x0 - e[0], r.x1 + e[2]);
    const double y = span(r.y0 - e[1], r.y1 + e[3]);
    return (reach(r.x0, e[0]) + reach(r.x1, e[2])) * y +
           (reach(r.y0, e[1]) + reach(r.y1, e[3])) * x;
  }
  // Whether `r`, a patch at depth z, reaches the light, and whether float32
  // might say otherwise: an edge within its error, and the light's float
  // size, of the light's.
  bool touches(const PlaneRect& r, double z, bool& close) const {
    auto near = [&](double edge, double bound, int axis) {
      return std::abs(edge - bound) <= edge_error(edge, z, axis) + 1e-6 * (std::abs(edge) + half_);
    };
    close = close || near(r.x0, half_, 0) || near(r.y0, half_, 1) || near(r.x1, -half_, 0) ||
            near(r.y1, -half_, 1);
    return r.x0 <= half_ && r.y0 <= half_ && r.x1 >= -half_ && r.y1 >= -half_;
  }
  double half() const { return half_; }

 private:
  const ShadowMapView& map_;
  const LightParams& light_;
  const Query& q_;
  double to_slope_;
  double half_;
};

struct WalkEnd {
  bool truncated = false;  // stopped by `steps` or max_nodes, not by the walk's own end
  bool coarse = false;     // took a node whole that it would have descended
  bool close = false;      // a float32 decision steering the walk was too close to call
};

// Walks `window` (non-empty, inside the map) for at most `steps` steps as
// the shader does, calling add(texels, z) for each patch it hands over
// (texels at linear depth z) and stopping once covered() holds. With
// `coarse` (the shader's BACKPROJECTION_FINISH_COARSE), the min-max walk
// hands a node the steps left cannot refine (steps_to_end()) whole to
// coarse(texels, range), so that it finishes rather than stops; brute force
// stops either way.
template <typename Add, typename Covered, typename Coarse = std::nullptr_t>
WalkEnd walk_backprojection(const ShadowMapView& map, const MinMaxMip& mip,
                            const Projector& projector, float limit, const TexelRect& window,
                            const VariantKeys& keys, int steps, Add add, Covered covered,
                            Coarse coarse = nullptr) {
  const int max_nodes = keys.max_nodes.value_or(kDefaultMaxNodes);
  WalkEnd end;
  if (keys.traversal == kBruteForceTraversal) {
    const long long width = window.x1 - window.x0 + 1;
    long long n = 0;
    for (; n < std::min<long long>(window.count(), std::min(steps, max_nodes)) && !covered(); ++n) {
      const int i = window.x0 + int(n % width);
      const int j = window.y0 + int(n / width);
      const float depth = float(map.depth(i, j));
      if (depth < limit) add(TexelRect{i, j, i, j}, double(depth));
    }
    end.truncated = n < window.count() && !covered();
    return end;
  }
  MinmaxCursor cursor(window);
  int visits = 0;
  bool done = false;
  for (int step = 0; step < steps && !done; ++step) {
    bool descend = false;
    if (!cursor.climbed()) ++visits;
    if (!cursor.climbed() && !intersect(cursor.texels(), window).empty()) {
      const MinMax range = mip.node(cursor.level(), cursor.x(), cursor.y());
      const TexelRect texels = clip(cursor.texels(), map.width(), map.height());
      if (range.min < limit &&
          projector.touches(projector.project(texels, range.min), range.min, end.close)) {
        // Flat: its texels tile one patch (level 0 always is: min == max).
        const bool flat = range.max < limit && range.min == range.max;
        descend = !flat;
        if constexpr (!std::is_null_pointer_v<Coarse>) {
          // Descend only where the walk still ends within its steps.
          descend = descend && cursor.steps_to_end() + 4 <= steps - step - 1;
          if (!flat && !descend) {
            end.coarse = true;
            coarse(texels, range);
          }
        }
        if (flat) add(texels, double(range.min));
      }
    }
    if (descend) {
      cursor.descend();
    } else {
      cursor.next();
    }
    done = cursor.done() || covered() || visits >= max_nodes;
  }
  end.truncated = !cursor.done() && !covered();
  return end;
}

}  // namespace penumbra::reference::detail
