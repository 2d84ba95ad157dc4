// A read-only view of a shadow map as linear light-view z, with the
// docs/shader-interface.md's texel addressing (clamp-to-edge): a map of
// linear z, or one stored in another encoding and decoded texel by texel.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "penumbra/model/depth_format.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/support/image.hpp"

namespace penumbra::reference {

// A map stored as an engine's depth buffer holds it (map_encoding.hpp).
struct EncodedDepth {
  MapEncoding encoding = MapEncoding::perspective;
  DepthRange range;
  DepthFormat format = DepthFormat::d32_float;  // the depth texture holding it
};

// How far from a texel's depth z a receiver's (biased) depth must lie for
// every conformant shader to compare it as the exact decoding does: the
// shader encodes the reference in float32 (a subtraction and a division
// over operands the size of 1, within 16 ulp of 1 in the stored value) and
// rounds z_r - bias (a quarter of that, relative to z). A unorm map adds one
// step of its format: hardware may compare at the texture's precision,
// rounding the reference to a neighbouring code.
double tie_margin(const EncodedDepth& encoded, double z);

class ShadowMapView {
 public:
  // Reads channel 0 of `depth`, linear z; the image must outlive the view.
  explicit ShadowMapView(const FloatImage& depth) : image_(&depth) {}
  // Reads channel 0 of `stored`, values in `encoded`'s encoding, each
  // decoded depth moved `shift` (-1, 0 or +1) tie_margin()s away from the
  // light, to find the receivers a shader's rounding decides.
  ShadowMapView(const FloatImage& stored, const EncodedDepth& encoded, int shift = 0)
      : image_(&stored), encoded_(encoded), shift_(shift) {}

  int width() const { return image_->width; }
  int height() const { return image_->height; }

  // Depth of texel (i, j); indices outside the map take the nearest edge texel.
  // A NaN texel reads as +inf: it occludes nothing (docs/robustness.md).
  double depth(int i, int j) const {
    const double z = image_->at(std::clamp(i, 0, width() - 1), std::clamp(j, 0, height() - 1));
    if (std::isnan(z)) return std::numeric_limits<double>::infinity();
    return encoded_ ? decoded(z) : z;
  }

 private:
  double decoded(double stored) const {
    const double z = decode_depth(encoded_->encoding, stored, encoded_->range);
    return std::isfinite(z) ? z + shift_ * tie_margin(*encoded_, z) : z;
  }

  const FloatImage* image_;
  std::optional<EncodedDepth> encoded_;
  int shift_ = 0;
};

}  // namespace penumbra::reference
