// The shadow map's min-max mip (docs/gl.md, "The min-max mip"), built on the
// current context by a variant's minmax_init and minmax_reduce passes.
#pragma once

#include <optional>
#include <vector>

#include "gl_names.hpp"
#include "pass_inputs.hpp"
#include "pass_program.hpp"
#include "penumbra/gl/engine.hpp"
#include "penumbra/support/image.hpp"
#include "penumbra/support/minmax_levels.hpp"
#include "penumbra/support/param_block.hpp"
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

// Prepares both passes, then draws level 1 with minmax_init reading what
// `inputs` gives it (the map, map_size, as shadow_depth) and each level l up
// to N with minmax_reduce reading level l - 1 as minmax_source, each into a
// texture of its own that is then copied into the chain. Each draw gets
// `params` with source_size set to the level it reads and screen_size to the
// level it writes (W, H, 1/W, 1/H). Errors: those of prepare_pass and
// draw_full_screen, naming the pass (and the level); bad_input when the two
// passes' render targets differ in format.
Result<MinmaxMip> build_minmax_mip(const GlMinmaxPasses& passes, PassInputs& inputs,
                                   LevelSize map_size, const ParamBlock& params);

// When the prepared `pass` reads shadow_minmax: builds the mip with
// `minmax` from what `inputs` gives (the map, `map_size`) and gives it to
// `inputs` as shadow_minmax. Returns the mip, which must outlive the draw, or
// none. Errors: bad_input when `pass` reads the mip and `minmax` is empty;
// build_minmax_mip's.
Result<std::optional<MinmaxMip>> give_minmax_mip(const PassProgram& pass,
                                                 const std::optional<GlMinmaxPasses>& minmax,
                                                 PassInputs& inputs, LevelSize map_size,
                                                 const ParamBlock& params);

// Levels 1..N (index 0 is level 1) at their sizes, every channel of the
// chain's format ((min, max)).
Result<std::vector<FloatImage>> read_minmax_mip(const MinmaxMip& mip);

}  // namespace penumbra::gl
