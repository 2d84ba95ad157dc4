#include "shading.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace penumbra::report {
namespace {

using reference::Surface;

constexpr Rgb kBackground{0.012f, 0.014f, 0.018f};
constexpr Rgb kGround{0.78f, 0.76f, 0.72f};
constexpr Rgb kBox{0.42f, 0.55f, 0.75f};
constexpr Rgb kUnmeasured{0.05f, 0.05f, 0.05f};
constexpr float kAmbient = 0.12f;

Rgb scaled(Rgb c, float k) {
  return {c.r * k, c.g * k, c.b * k};
}

Rgb ramp(double t) {
  // Black, purple, red, orange, yellow at equal steps (linear values).
  constexpr std::array<Rgb, 5> kStops{{{0.0f, 0.0f, 0.0f},
                                       {0.13f, 0.01f, 0.30f},
                                       {0.70f, 0.03f, 0.05f},
                                       {0.95f, 0.35f, 0.01f},
                                       {1.0f, 0.95f, 0.30f}}};
  const double at = std::clamp(t, 0.0, 1.0) * (kStops.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(at), kStops.size() - 2);
  const auto f = static_cast<float>(at - double(i));
  const Rgb& a = kStops[i];
  const Rgb& b = kStops[i + 1];
  return {a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f};
}

}  // namespace

Picture shade(const reference::StageView& view, const FloatImage& visibility) {
  Picture picture(visibility.width, visibility.height);
  for (int y = 0; y < picture.height; ++y) {
    for (int x = 0; x < picture.width; ++x) {
      const float v = std::clamp(visibility.at(x, y), 0.0f, 1.0f);
      switch (view.surfaces[std::size_t(y) * picture.width + x]) {
        case Surface::none:
          picture.set(x, y, kBackground);
          break;
        case Surface::ground:
          picture.set(x, y, scaled(kGround, kAmbient + (1 - kAmbient) * v));
          break;
        case Surface::top:
          picture.set(x, y, scaled(kBox, kAmbient + (1 - kAmbient) * v));
          break;
        case Surface::side:
          picture.set(x, y, scaled(kBox, 2 * kAmbient));
          break;
      }
    }
  }
  return picture;
}

Picture heatmap(const reference::StageView& view, const FloatImage& a, const FloatImage& b) {
  Picture picture(a.width, a.height);
  for (int y = 0; y < picture.height; ++y) {
    for (int x = 0; x < picture.width; ++x) {
      const Surface s = view.surfaces[std::size_t(y) * picture.width + x];
      if (!reference::receives_light(s)) {
        picture.set(x, y, s == Surface::none ? kBackground : kUnmeasured);
        continue;
      }
      const double error = std::abs(double(a.at(x, y)) - double(b.at(x, y)));
      // A NaN is as wrong as it gets.
      picture.set(x, y, ramp(std::isnan(error) ? 1.0 : error / kHeatmapFullScale));
    }
  }
  return picture;
}

Picture crop_scaled(const Picture& picture, const Crop& crop, int scale) {
  Picture out(crop.width * scale, crop.height * scale);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      const int sx = std::clamp(crop.x + x / scale, 0, picture.width - 1);
      const int sy = std::clamp(crop.y + y / scale, 0, picture.height - 1);
      std::copy_n(&picture.rgb[(std::size_t(sy) * picture.width + sx) * 3], 3,
                  &out.rgb[(std::size_t(y) * out.width + x) * 3]);
    }
  }
  return out;
}

Picture side_by_side(const std::vector<Picture>& panels, int gap) {
  int width = 0, height = 0;
  for (const Picture& p : panels) {
    width += p.width + (width > 0 ? gap : 0);
    height = std::max(height, p.height);
  }
  Picture out(width, height);
  int left = 0;
  for (const Picture& p : panels) {
    for (int y = 0; y < p.height; ++y) {
      std::copy_n(&p.rgb[std::size_t(y) * p.width * 3], std::size_t(p.width) * 3,
                  &out.rgb[(std::size_t(y) * out.width + left) * 3]);
    }
    left += p.width + gap;
  }
  return out;
}

}  // namespace penumbra::report
