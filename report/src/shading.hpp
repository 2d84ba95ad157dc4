// The report's pictures: the stage shaded by a visibility image, error
// heatmaps, and the contact sheet's crops.
#pragma once

#include <vector>

#include "penumbra/reference/stage.hpp"
#include "png_file.hpp"

namespace penumbra::report {

// |error| at or above this is drawn at the heatmap's top colour.
inline constexpr double kHeatmapFullScale = 0.25;

// The stage lit through `visibility` (1 channel, the view's size): ground
// and box tops get ambient plus the light times visibility; box sides,
// which the light grazes, ambient only.
Picture shade(const reference::StageView& view, const FloatImage& visibility);

// |a - b| on the pixels that receive light face-on, from black (0) through
// purple and red to yellow (kHeatmapFullScale and above); other pixels grey.
Picture heatmap(const reference::StageView& view, const FloatImage& a, const FloatImage& b);

struct Crop {
  int x = 0, y = 0, width = 0, height = 0;
};

// `crop` of `picture`, each pixel drawn as scale x scale.
Picture crop_scaled(const Picture& picture, const Crop& crop, int scale);

// `panels` (one height) left to right, `gap` background pixels apart.
Picture side_by_side(const std::vector<Picture>& panels, int gap);

}  // namespace penumbra::report
