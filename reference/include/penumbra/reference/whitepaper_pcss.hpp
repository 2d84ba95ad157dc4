// The PCSS shader code ("PCSS Shader Code") of the NVIDIA PCSS whitepaper,
// "Integrating Realistic Soft Shadows into Your Game Engine" (2008),
// transliterated line by line to C++ with its own constants and 16-point
// Poisson disk. A second, independent reading of the specification that the
// pcss reference (and `penumbra eval`) is checked against.
#pragma once

#include <array>

#include "penumbra/model/model.hpp"
#include "penumbra/reference/shadow_map.hpp"

namespace penumbra::reference {

// The whitepaper's poissonDisk[16] as float32, point for point.
const std::array<Point2, 16>& whitepaper_poisson_disk();

// PCSS(shadowMapTex, coords) for coords = (u, v, z_receiver), z in linear
// light-view z, with the whitepaper's #defines (16 + 16 samples, L = 0.5,
// Fw = 3.75, n = 9.5, no bias).
double whitepaper_pcss(const ShadowMapView& map, double u, double v, double z_receiver);

}  // namespace penumbra::reference
