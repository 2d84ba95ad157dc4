// A run's error figures on the stage (docs/verification.md, "Report"):
// each named for the truth it is measured against.
#pragma once

#include <nlohmann/json.hpp>

#include "penumbra/reference/stage.hpp"

namespace penumbra::report {

// Over the pixels that receive light face-on (ground and box tops); the
// penumbra is where the exact truth is strictly between 0 and 1.
struct Figures {
  double exact_penumbra_mae = 0.0;   // mean |visibility - exact| over the penumbra
  double exact_penumbra_rmse = 0.0;  // root mean square of the same
  double exact_penumbra_max = 0.0;   // largest of the same
  double exact_rmse = 0.0;           // over every measured pixel: leaks and acne count too
  double exact_max = 0.0;
  // |visibility - CPU reference| over the measured pixels the reference
  // decides (not ambiguous), as verify compares them.
  double reference_mae = 0.0;
  double reference_max = 0.0;
  double texel_reads_per_pixel = 0.0;  // the query's mean texel reads per measured pixel
  double texel_reads_max = 0.0;
};

// The pixels a run is measured over.
struct Region {
  std::size_t measured = 0;  // receiving light face-on
  std::size_t penumbra = 0;  // of those, exact truth strictly in (0, 1)
};

Region region(const reference::StageView& view, const FloatImage& exact);

// `reference_ambiguous`: non-zero where the reference is undecided (PictureRun).
Figures measure(const reference::StageView& view, const FloatImage& exact,
                const FloatImage& visibility, const FloatImage& reference,
                const FloatImage& reference_ambiguous, const FloatImage& texel_reads);

nlohmann::json to_json(const Figures& figures);

}  // namespace penumbra::report
