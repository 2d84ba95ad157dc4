#include "disk/generators.hpp"

namespace penumbra::disk_detail {

// The top 53 bits scaled by 2^-53: exact in IEEE-754 double, so the value
// depends only on the engine's output.
double UnitDiskSampler::next_unit() {
  return static_cast<double>(engine_() >> 11) * 0x1.0p-53;
}

// Rejection from the square [-1, 1]^2. Rounding to float32 happens before the
// radius test, so the points that are kept (and baked) are inside the disk.
Point2 UnitDiskSampler::next() {
  for (;;) {
    const Point2 p = {static_cast<float>(2.0 * next_unit() - 1.0),
                      static_cast<float>(2.0 * next_unit() - 1.0)};
    if (squared_distance(p, {0.0f, 0.0f}) <= 1.0) return p;
  }
}

double squared_distance(const Point2& a, const Point2& b) {
  const double dx = static_cast<double>(a[0]) - static_cast<double>(b[0]);
  const double dy = static_cast<double>(a[1]) - static_cast<double>(b[1]);
  return dx * dx + dy * dy;
}

}  // namespace penumbra::disk_detail
