// The min-max mip's level sizes (docs/shader-interface.md, "The min-max
// mip"), for every engine and the reference alike.
#pragma once

#include <array>
#include <vector>

namespace penumbra {

struct LevelSize {
  int width = 0;
  int height = 0;
};

// N, the top level (1x1): the smallest N >= 1 with 2^N >= max(width, height).
int minmax_top_level(int width, int height);

// Hierarchy levels 1..N of a width x height map (index 0 is level 1), each
// half the one below rounded up, so a level covers every texel below it.
std::vector<LevelSize> minmax_level_sizes(int width, int height);

// Side of the square chain that stores the levels: 2^(N-1). Graphics APIs
// halve mip sizes rounding down, so mip m of this chain, 2^(N-1-m) square,
// holds hierarchy level m + 1 at texel (0, 0), and node (i, j) of level l
// is read at uv ((i, j) + 0.5) * 2^(l-N) on every API.
int minmax_chain_side(int width, int height);

// (W, H, 1/W, 1/H): how ShadowParams' size members hold a size.
std::array<float, 4> size_vec4(int width, int height);

}  // namespace penumbra
