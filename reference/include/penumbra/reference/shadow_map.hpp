// A read-only view of a shadow map as linear light-view z, with the
// docs/shader-interface.md's texel addressing (clamp-to-edge): a map of
// linear z, or one stored in another encoding and decoded texel by texel.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "penumbra/model/depth_format.hpp"
#include "penumbra/model/light.hpp"
#include "penumbra/model/map_encoding.hpp"
#include "penumbra/support/image.hpp"

namespace penumbra::reference {

// A map stored as an engine's depth buffer holds it (map_encoding.hpp).
struct EncodedDepth {
  MapEncoding encoding = MapEncoding::perspective;
  DepthRange range;
  DepthFormat format = DepthFormat::d32_float;  // the depth texture holding it

  bool operator==(const EncodedDepth&) const = default;
};

// How a map in `encoding` stores depth under the projection these
// parameters describe: `light`'s near plane, and 1 / depth_scale for the far
// one (docs/shader-interface.md); none for linear z.
std::optional<EncodedDepth> encoded_depth(MapEncoding encoding, const LightParams& light,
                                          float depth_scale);

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
  // Reads channel 0 of `depth`, linear z. Copies it, once: the reference
  // reads each texel many times.
  explicit ShadowMapView(const FloatImage& depth);
  // Reads channel 0 of `stored`, values in `encoded`'s encoding, each
  // decoded depth moved `shift` (-1, 0 or +1) tie_margin()s away from the
  // light, to find the receivers a shader's rounding decides. Decodes every
  // texel once, here.
  ShadowMapView(const FloatImage& stored, const EncodedDepth& encoded, int shift = 0);

  int width() const { return width_; }
  int height() const { return height_; }

  // Depth of texel (i, j); indices outside the map take the nearest edge texel.
  // A NaN texel reads as +inf: it occludes nothing (docs/robustness.md).
  double depth(int i, int j) const {
    const int ci = std::clamp(i, 0, width_ - 1);
    const int cj = std::clamp(j, 0, height_ - 1);
    return row(cj)[ci];
  }
  // The depths of row j (0 <= j < height()), as depth() reads them.
  const double* row(int j) const { return depths_->data() + std::size_t(j) * std::size_t(width_); }

 private:
  std::shared_ptr<const std::vector<double>> depths_;  // row 0 first, views share them
  int width_ = 0;
  int height_ = 0;
};

}  // namespace penumbra::reference
