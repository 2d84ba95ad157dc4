#include "ray_box.hpp"

#include <algorithm>
#include <limits>

namespace penumbra::reference {

std::optional<BoxHit> ray_box(const Box& box, const std::array<double, 3>& origin,
                              const std::array<double, 3>& direction) {
  const double lows[3] = {box.x0, box.y0, box.z0};
  const double highs[3] = {box.x1, box.y1, box.z1};
  // The ray is inside the box for t in the intersection of one interval per
  // axis; it enters through the face of the interval that starts last.
  BoxHit hit{0.0, 2, true};
  double enter = 0.0;
  double leave = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    if (direction[axis] == 0.0) {
      if (origin[axis] < lows[axis] || origin[axis] > highs[axis]) return std::nullopt;
      continue;
    }
    const double t_low = (lows[axis] - origin[axis]) / direction[axis];
    const double t_high = (highs[axis] - origin[axis]) / direction[axis];
    const double near = std::min(t_low, t_high);
    if (near > enter) hit = {near, axis, t_low < t_high};
    enter = std::max(enter, near);
    leave = std::min(leave, std::max(t_low, t_high));
  }
  if (enter > leave) return std::nullopt;
  hit.t = enter;
  return hit;
}

}  // namespace penumbra::reference
