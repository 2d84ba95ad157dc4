// The shadow map's min-max mip (docs/gl.md, "The min-max mip") on the
// current context, gathered from the levels a variant's minmax_init and
// minmax_reduce passes drew.
#pragma once

#include <span>
#include <vector>

#include "gl_names.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/minmax_levels.hpp"
#include "penumbra/support/result.hpp"
#include "texel_formats.hpp"

namespace penumbra::gl {

// Hierarchy level l (1..N) in level l - 1 of a texture whose level 0 is
// 2^(N-1) x 2^(N-1), at texels [0, sizes[l - 1]); the rest of each level
// is padding, 1 in every channel.
struct MinmaxMip {
  Texture chain;
  const TexelFormat* format = nullptr;  // the passes' render-target format
  std::vector<LevelSize> sizes;         // minmax_level_sizes of the map
};

// The mip of a map of `map_size` from its levels 1..N, each drawn by a
// min-max pass into a texture of its own in `format`. Errors: device for a
// GL error.
Result<MinmaxMip> gather_minmax_mip(std::span<const Texture* const> levels,
                                    const TexelFormat& format, LevelSize map_size);

// Levels 1..N (index 0 is level 1) at their sizes, every channel of the
// chain's format ((min, max)).
Result<std::vector<FloatImage>> read_minmax_mip(const MinmaxMip& mip);

}  // namespace penumbra::gl
