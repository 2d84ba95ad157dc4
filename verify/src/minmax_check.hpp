// A target's min-max mip, built on the device by its own minmax passes,
// checked bit for bit against the CPU mip of the same map.
#pragma once

#include <vector>

#include "penumbra/verify/verify.hpp"
#include "scene_fixture.hpp"

namespace penumbra {

// `levels`: Engine::read_minmax of the fixture's map (levels 1..N, normalized
// depth). The CPU mip is built from the map as the device stores it, so every
// min and max must be the same float.
MinmaxCheck check_minmax(const SceneFixture& fixture, Target target,
                         const std::vector<FloatImage>& levels);

}  // namespace penumbra
