// The pass list verify runs for a variant on a scene, and what its targets
// say: the one place verify reads a technique's passes, so that no backend
// names a technique.
#pragma once

#include <vector>

#include "penumbra/library/library.hpp"
#include "penumbra/runtime/pass_driver.hpp"
#include "penumbra/vulkan/engine.hpp"

namespace penumbra {

// `entry`'s technique's passes over a scene whose map is given
// (TechniqueDescription::passes): no depth pass, the query rather than the
// deferred pass, and the min-max passes only where `builds_mip` (a path that
// builds the mip of its own map; the Vulkan paths read the fixture's).
std::vector<PassKind> scene_passes(const LibraryVariant& entry, bool builds_mip);

// The visibility the passes end in: .x of the last screen pass that writes
// a factor (after a blur, the blurred one; not the composite's colour),
// with the first pass's texel reads and the draws' GPU time.
QueryOutput final_visibility(const runtime::PassOutputs& outputs);

}  // namespace penumbra
