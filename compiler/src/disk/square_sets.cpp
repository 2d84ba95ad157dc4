// Sample sets whose footprint is a square: scaled by a filter radius they
// cover the square area light's own shape, which a round disk does not (the
// convolution formulation of soft shadows, Soler and Sillion 1998).
#include <cmath>

#include "disk/generators.hpp"

namespace penumbra::disk_detail {
namespace {

Point2 to_square(double x, double y) {
  return {static_cast<float>(2.0 * x - 1.0), static_cast<float>(2.0 * y - 1.0)};
}

}  // namespace

std::vector<Point2> square_stratified(int count, UnitDiskSampler& sampler) {
  std::vector<Point2> points;
  points.reserve(static_cast<std::size_t>(count));
  const int rows = std::max(1, static_cast<int>(std::floor(std::sqrt(double(count)))));
  double bottom = 0.0;
  for (int r = 0; r < rows; ++r) {
    // The first count % rows bands get one cell more; every cell has area 1 / count.
    const int cells = count / rows + (r < count % rows ? 1 : 0);
    const double height = double(cells) / count;
    for (int c = 0; c < cells; ++c) {
      const double x = (c + sampler.next_unit()) / cells;
      const double y = bottom + sampler.next_unit() * height;
      points.push_back(to_square(x, y));
    }
    bottom += height;
  }
  return points;
}

std::vector<Point2> square_r2(int count, UnitDiskSampler& sampler) {
  // The plastic number g, the root of x^3 = x + 1, gives R2's steps 1/g and
  // 1/g^2 (Roberts 2018, "The Unreasonable Effectiveness of Quasirandom
  // Sequences").
  constexpr double kG = 1.32471795724474602596;
  constexpr double kStepX = 1.0 / kG;
  constexpr double kStepY = 1.0 / (kG * kG);
  const double shift_x = sampler.next_unit();
  const double shift_y = sampler.next_unit();
  std::vector<Point2> points;
  points.reserve(static_cast<std::size_t>(count));
  for (int i = 1; i <= count; ++i) {
    const double x = shift_x + i * kStepX;
    const double y = shift_y + i * kStepY;
    points.push_back(to_square(x - std::floor(x), y - std::floor(y)));
  }
  return points;
}

}  // namespace penumbra::disk_detail
