#include "penumbra/model/depth_format.hpp"

#include <cmath>

#include "penumbra/model/enum_names.hpp"

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

float unorm_depth(DepthFormat format, std::uint32_t code) {
  return static_cast<float>(code * depth_step(format));
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
  return parse_enum(kAllDepthFormats, name);
}

std::string allowed_depth_formats() {
  return enum_names(kAllDepthFormats);
}

}  // namespace penumbra
