// A read-only view of a shadow map holding *linear* light-view z, with the
// docs/shader-interface.md's texel addressing (clamp-to-edge).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "penumbra/support/image.hpp"

namespace penumbra::reference {

class ShadowMapView {
 public:
  // Reads channel 0 of `depth`; the image must outlive the view.
  explicit ShadowMapView(const FloatImage& depth) : image_(&depth) {}

  int width() const { return image_->width; }
  int height() const { return image_->height; }

  // Depth of texel (i, j); indices outside the map take the nearest edge texel.
  // A NaN texel reads as +inf: it occludes nothing (docs/robustness.md).
  double depth(int i, int j) const {
    const double z = image_->at(std::clamp(i, 0, width() - 1), std::clamp(j, 0, height() - 1));
    return std::isnan(z) ? std::numeric_limits<double>::infinity() : z;
  }

 private:
  const FloatImage* image_;
};

}  // namespace penumbra::reference
