// Where a ray first meets a box of a scene (the slab test).
#pragma once

#include <array>
#include <optional>

#include "penumbra/reference/scene.hpp"

namespace penumbra::reference {

struct BoxHit {
  double t = 0.0;   // the ray's parameter at the hit: origin + t direction
  int axis = 2;     // the face's normal axis: 0 x, 1 y, 2 z
  bool low = true;  // the face at the box's low coordinate on that axis (x0, y0, z0)
};

// The first point at t >= 0 of origin + t direction inside `box`; none when
// the ray misses it. A ray starting inside the box hits at t = 0.
std::optional<BoxHit> ray_box(const Box& box, const std::array<double, 3>& origin,
                              const std::array<double, 3>& direction);

}  // namespace penumbra::reference
