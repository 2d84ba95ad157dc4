#include "penumbra/reference/shadow_map.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace penumbra::reference {

std::optional<EncodedDepth> encoded_depth(MapEncoding encoding, const LightParams& light,
                                          float depth_scale) {
  if (encoding == MapEncoding::linear) return std::nullopt;
  return EncodedDepth{encoding, {light.near_plane, 1.0 / depth_scale}};
}

double tie_margin(const EncodedDepth& encoded, double z) {
  constexpr double kStoredReach = 0x1p-20;    // 16 ulp of 1
  constexpr double kReceiverReach = 0x1p-22;  // 4 ulp of z
  const double stored_reach = kStoredReach + depth_step(encoded.format);
  return stored_reach * depth_per_unit(encoded.encoding, z, encoded.range) + kReceiverReach * z;
}

ShadowMapView::ShadowMapView(const FloatImage& depth) : width_(depth.width), height_(depth.height) {
  std::vector<double> depths(depth.pixel_count());
  for (std::size_t k = 0; k < depths.size(); ++k) {
    const double z = depth.data[k * std::size_t(depth.channels)];
    depths[k] = std::isnan(z) ? std::numeric_limits<double>::infinity() : z;
  }
  depths_ = std::make_shared<const std::vector<double>>(std::move(depths));
}

ShadowMapView::ShadowMapView(const FloatImage& stored, const EncodedDepth& encoded, int shift)
    : width_(stored.width), height_(stored.height) {
  std::vector<double> depths(stored.pixel_count());
  for (std::size_t k = 0; k < depths.size(); ++k) {
    const double d = stored.data[k * std::size_t(stored.channels)];
    const double z = std::isnan(d) ? std::numeric_limits<double>::infinity()
                                   : decode_depth(encoded.encoding, d, encoded.range);
    depths[k] = std::isfinite(z) ? z + shift * tie_margin(encoded, z) : z;
  }
  depths_ = std::make_shared<const std::vector<double>>(std::move(depths));
}

}  // namespace penumbra::reference
