// A target's min-max mip, built on the device by its own minmax passes,
// checked against the CPU mip of the same map: bit for bit on the library's
// linear map, within float32's decoding error on an engine's.
#pragma once

#include <vector>

#include "penumbra/verify/verify.hpp"
#include "scene_fixture.hpp"

namespace penumbra {

// `levels`: Engine::read_minmax of the fixture's map (levels 1..N, normalized
// linear depth). On a linear map the CPU mip is built from the map as the
// device stores it, so every min and max must be the same float; on an
// encoded one from its exact decoding, times depth_scale.
MinmaxCheck check_minmax(const SceneFixture& fixture, Target target,
                         const std::vector<FloatImage>& levels);

}  // namespace penumbra
