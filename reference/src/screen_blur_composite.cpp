// screen_blur's composite pass and the scene colour its verification
// composites onto (docs/verification.md, "screen_blur").
#include "penumbra/reference/screen_blur.hpp"

namespace penumbra::reference {

FloatImage composite(const FloatImage& colour, const FloatImage& blurred) {
  FloatImage out(colour.width, colour.height, 4);
  for (int y = 0; y < colour.height; ++y) {
    for (int x = 0; x < colour.width; ++x) {
      const float factor = blurred.at(x, y, 0);
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = colour.at(x, y, c) * factor;
      out.at(x, y, 3) = colour.at(x, y, 3);
    }
  }
  return out;
}

FloatImage scene_colour(int width, int height) {
  constexpr float kEven[3] = {1.0f, 0.5f, 0.25f};
  constexpr float kOdd[3] = {0.25f, 0.75f, 1.0f};
  FloatImage out(width, height, 4);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const bool odd = (x / kSceneColourCell + y / kSceneColourCell) % 2 == 1;
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = odd ? kOdd[c] : kEven[c];
      out.at(x, y, 3) = 1.0f;
    }
  }
  return out;
}

}  // namespace penumbra::reference
