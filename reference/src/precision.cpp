// Tolerances from the error model in docs/verification.md.
#include "penumbra/reference/precision.hpp"

namespace penumbra::reference {
namespace {

// Float32 arithmetic and storage of a visibility in [0, 1] stay well below this.
constexpr double kFloatSlack = 1e-5;

}  // namespace

double tolerance(Technique technique, const SamplingPrecision& precision) {
  switch (technique) {
    case Technique::hard:
      // Point samples give exactly 0 or 1; the GPU can only differ by reading
      // another texel, and those pixels are marked ambiguous and skipped.
      return kFloatSlack;
    case Technique::screen_blur:
      // The factor: a mean of 9 such point samples, n / 9 for an integer n,
      // as exact as hard's once an ambiguous sample marks the pixel; float
      // rounding of n / 9 is far below the slack. (The blur and composite
      // are checked against the CPU chain run on the GPU's own images:
      // docs/verification.md, "screen_blur".)
      return kFloatSlack;
    case Technique::minmax_pcf:
      // An integer count of point compares, 1 - C / K^2 in float: bit-exact.
      return 0.0;
    case Technique::backprojection:
      // Exact compares; only float32 sums of patch areas differ.
      return 1e-4;
    case Technique::pcf_grid:
    case Technique::pcf_poisson:
    case Technique::pcss:
    case Technique::pcss_minmax:
      // A bilinear comparison is w . c with c in {0, 1}^4. If each axis
      // weight is off by at most one step e, the blend moves by at most
      // |da| + |db| <= 2e, and a mean of such samples by no more.
      return 2 * precision.step() + kFloatSlack;
  }
  return kFloatSlack;
}

}  // namespace penumbra::reference
