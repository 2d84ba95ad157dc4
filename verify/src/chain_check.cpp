#include "chain_check.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace penumbra {

Result<ChainCheck> check_chain(const FloatImage& gpu, const FloatImage& cpu, double tolerance,
                               std::string_view what) {
  if (gpu.width != cpu.width || gpu.height != cpu.height || gpu.channels != cpu.channels) {
    return make_error(Error::Kind::bad_input, std::string(what),
                      "the GPU image is " + std::to_string(gpu.width) + "x" +
                          std::to_string(gpu.height) + "x" + std::to_string(gpu.channels) +
                          " but the reference is " + std::to_string(cpu.width) + "x" +
                          std::to_string(cpu.height) + "x" + std::to_string(cpu.channels));
  }
  ChainCheck check;
  check.tolerance = tolerance;
  check.values = gpu.data.size();
  for (std::size_t i = 0; i < gpu.data.size(); ++i) {
    const double error = std::abs(double(gpu.data[i]) - double(cpu.data[i]));
    if (std::isnan(error)) {
      check.max_abs_error = std::numeric_limits<double>::infinity();
      ++check.over_tolerance;
      continue;
    }
    if (error > check.max_abs_error) check.max_abs_error = error;
    if (error > tolerance) ++check.over_tolerance;
  }
  check.pass = check.values > 0 && check.over_tolerance == 0;
  return check;
}

}  // namespace penumbra
