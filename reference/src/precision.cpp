// Tolerances from the error model in docs/verification.md, per technique in
// technique_table.cpp.
#include "penumbra/reference/precision.hpp"

#include <algorithm>
#include <cmath>

#include "technique_table.hpp"

namespace penumbra::reference {

double atlas_coordinate_error(int width, int height) {
  return std::ldexp(double(std::max(width, height)), -22);
}

double tolerance(Technique technique, const SamplingPrecision& precision) {
  return detail::reference_for(technique).tolerance(precision);
}

}  // namespace penumbra::reference
