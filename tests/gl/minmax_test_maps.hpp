// What the GL min-max tests share: maps without a pattern a reduction could
// hide, the brute-force (min, max) of a hierarchy node, ShadowParams for a
// bare map, and the emitted min-max passes of the default library.
#pragma once

#include <array>

#include "gl_fixture.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/param_block.hpp"

namespace penumbra::testing {

// Normalized depth in [0, 1), a hash of each texel.
FloatImage hashed_map(int width, int height);

// (min, max) of the map texels [i 2^l, (i+1) 2^l) x [j 2^l, (j+1) 2^l)
// clipped to the map, texel by texel.
std::array<float, 2> brute_force_node(const FloatImage& map, int level, int i, int j);

// ShadowParams for `map` (depth scale 1, the first scene's light) and
// receivers of the given size.
ParamBlock bare_map_params(const FloatImage& map, int receivers_width, int receivers_height);

// minmax_pcf_k8's minmax_init and minmax_reduce for `target`; fails the test
// (and returns an empty text) when they do not compile.
MinmaxText default_minmax_passes(Target target);

}  // namespace penumbra::testing
