#include "penumbra/model/depth_format.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra {

int unorm_bits(DepthFormat format) {
  switch (format) {
    case DepthFormat::d32_float:
      return 0;
    case DepthFormat::d24_unorm:
      return 24;
    case DepthFormat::d16_unorm:
      return 16;
  }
  return 0;
}

double depth_step(DepthFormat format) {
  const int bits = unorm_bits(format);
  return bits == 0 ? 0.0 : 1.0 / (std::ldexp(1.0, bits) - 1.0);
}

unsigned unorm_code(DepthFormat format, double depth) {
  const int bits = unorm_bits(format);
  if (bits == 0) return 0;
  const double largest = std::ldexp(1.0, bits) - 1.0;
  // NaN clamps to 0, as the APIs' float-to-unorm conversion does.
  const double clamped = std::isnan(depth) ? 0.0 : std::clamp(depth, 0.0, 1.0);
  return static_cast<unsigned>(std::nearbyint(clamped * largest));
}

float stored_depth(DepthFormat format, double depth) {
  if (format == DepthFormat::d32_float) return static_cast<float>(depth);
  return static_cast<float>(unorm_code(format, depth) * depth_step(format));
}

std::string_view to_string(DepthFormat format) {
  switch (format) {
    case DepthFormat::d32_float:
      return "d32_float";
    case DepthFormat::d24_unorm:
      return "d24_unorm";
    case DepthFormat::d16_unorm:
      return "d16_unorm";
  }
  return "d32_float";
}

std::optional<DepthFormat> parse_depth_format(std::string_view name) {
  for (const DepthFormat format : kAllDepthFormats) {
    if (to_string(format) == name) return format;
  }
  return std::nullopt;
}

std::string allowed_depth_formats() {
  std::string out;
  for (const DepthFormat format : kAllDepthFormats) {
    out += (out.empty() ? "" : ", ") + std::string(to_string(format));
  }
  return out;
}

}  // namespace penumbra
