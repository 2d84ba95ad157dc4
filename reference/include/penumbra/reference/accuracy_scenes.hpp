// The accuracy suite: scenes that each stress one known failure of
// shadow-map soft shadows, measured against exact_visibility() by
// bench/bench_accuracy.cpp (docs/accuracy.md).
#pragma once

#include <vector>

#include "penumbra/reference/scene.hpp"

namespace penumbra::reference {

// "contact", "overlap", "thin", "large_light" and "slope"; names are unique and
// stable. Every occluder lies inside its map's frustum, so the exact truth
// depends on nothing a map cannot see. Maps are 512^2, receivers 96^2 over
// the receiver plane.
std::vector<Scene> accuracy_scenes();

}  // namespace penumbra::reference
