// The comparison metrics of docs/verification.md.
#include "penumbra/reference/compare.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

namespace penumbra::reference {
namespace {

std::string size_of(const FloatImage& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

}  // namespace

Result<Comparison> compare(const FloatImage& gpu, const FloatImage& reference,
                           const FloatImage& ambiguous, double tolerance) {
  for (const FloatImage* image : {&reference, &ambiguous}) {
    if (image->width != gpu.width || image->height != gpu.height) {
      return make_error(Error::Kind::bad_input, "compare",
                        "image sizes differ: GPU " + size_of(gpu) + ", reference " +
                            size_of(reference) + ", ambiguity mask " + size_of(ambiguous));
    }
  }
  Comparison result;
  result.pixels = gpu.pixel_count();
  result.tolerance = tolerance;
  double error_sum = 0.0;
  for (int j = 0; j < gpu.height; ++j) {
    for (int i = 0; i < gpu.width; ++i) {
      if (ambiguous.at(i, j) != 0.0f) {
        ++result.ambiguous;
        continue;
      }
      ++result.compared;
      double error = std::abs(double(gpu.at(i, j)) - double(reference.at(i, j)));
      // A NaN must fail: it compares false against any tolerance.
      if (std::isnan(error)) error = std::numeric_limits<double>::infinity();
      if (error > tolerance) ++result.over_tolerance;
      result.max_abs_error = std::max(result.max_abs_error, error);
      error_sum += error;
    }
  }
  if (result.compared > 0) result.mean_abs_error = error_sum / double(result.compared);
  // Nothing compared is nothing checked: an empty or all-ambiguous run fails.
  result.pass = result.compared > 0 && result.over_tolerance == 0 &&
                double(result.ambiguous) <= kMaxAmbiguousFraction * double(result.pixels);
  return result;
}

void to_json(nlohmann::json& json, const Comparison& c) {
  json = nlohmann::json{{"pixels", c.pixels},
                        {"compared", c.compared},
                        {"ambiguous", c.ambiguous},
                        {"over_tolerance", c.over_tolerance},
                        {"max_abs_error", c.max_abs_error},
                        {"mean_abs_error", c.mean_abs_error},
                        {"tolerance", c.tolerance},
                        {"pass", c.pass}};
}

}  // namespace penumbra::reference
