// The one triangle covering the whole clip-space square [-1, 1]^2, two
// floats (x, y) per vertex: every query pass draws it
// (docs/shader-interface.md).
#pragma once

#include <array>

namespace penumbra {

inline constexpr std::array<float, 6> kFullScreenTriangle = {-1.0f, -1.0f, 3.0f,
                                                             -1.0f, -1.0f, 3.0f};

}  // namespace penumbra
