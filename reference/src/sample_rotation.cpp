// The `rotation` key's per-pixel placement of a variant's samples, as
// shaderlib/common/disks.glsl computes it. The noise is interleaved gradient
// noise (Jimenez 2014, "Next Generation Post Processing in Call of Duty:
// Advanced Warfare") with its constants rounded to dyadic fractions, so
// that float32 computes it exactly for pixels below 4096 and the reference
// has the shader's value to the bit.
#include "penumbra/reference/sample_rotation.hpp"

#include <cmath>
#include <numbers>

namespace penumbra::reference {
namespace {

double fract(double x) {
  return x - std::floor(x);
}

// fract(52.984375 fract(0.067138671875 x + 0.005859375 y)): every product
// and sum is a multiple of 2^-18 below 2^24 of it, so exact in float32.
double gradient_noise(double x, double y) {
  return fract(52.984375 * fract(0.067138671875 * x + 0.005859375 * y));
}

}  // namespace

Disk placed_disk(const Disk& disk, const VariantKeys& keys, const Query& q, bool& ambiguous) {
  if (keys.rotation != kIgnRotation) return disk;
  const double x = q.pixel_x;
  const double y = q.pixel_y;
  Disk placed = disk;
  if (sample_shape(disk.method) == SampleShape::square) {
    // The square [-1, 1]^2 as a torus, shifted by the noise at (x, y) and
    // at (y, x): the footprint stays the light's square.
    const double shift[2] = {gradient_noise(x, y), gradient_noise(y, x)};
    for (Point2& p : placed.points) {
      for (int axis = 0; axis < 2; ++axis) {
        const double moved = double(p[axis]) * 0.5 + 0.5 + shift[axis];
        ambiguous = ambiguous || std::abs(moved - 1.0) <= 1e-6;
        p[axis] = float(fract(moved) * 2.0 - 1.0);
      }
    }
    return placed;
  }
  const double angle = 2.0 * std::numbers::pi * gradient_noise(x, y);
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  for (Point2& p : placed.points) {
    const double px = p[0];
    const double py = p[1];
    p = {float(px * c - py * s), float(px * s + py * c)};
  }
  return placed;
}

}  // namespace penumbra::reference
