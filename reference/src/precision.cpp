// Tolerances from the error model in docs/verification.md, per technique in
// technique_table.cpp.
#include "penumbra/reference/precision.hpp"

#include "technique_table.hpp"

namespace penumbra::reference {

double tolerance(Technique technique, const SamplingPrecision& precision) {
  return detail::reference_for(technique).tolerance(precision);
}

}  // namespace penumbra::reference
