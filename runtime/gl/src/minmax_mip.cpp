#include "minmax_mip.hpp"

#include <string>

#include "gl_check.hpp"
#include "penumbra/support/minmax_levels.hpp"
#include "textures.hpp"

namespace penumbra::gl {

// The chain is 2^(N-1) square, as in the Vulkan runtime (minmax_chain_side
// in penumbra/support/minmax_levels.hpp says why). No level is ever drawn
// while it is sampled: each was drawn into its own texture, which the next
// reduce pass read and glCopyImageSubData copies into the chain.
Result<MinmaxMip> gather_minmax_mip(std::span<const Texture* const> levels,
                                    const TexelFormat& format, LevelSize map_size) {
  MinmaxMip mip;
  mip.format = &format;
  mip.sizes = minmax_level_sizes(map_size.width, map_size.height);
  if (levels.size() != mip.sizes.size()) {
    return make_error(Error::Kind::internal, "the min-max mip",
                      std::to_string(levels.size()) + " levels drawn for a map of " +
                          std::to_string(mip.sizes.size()));
  }
  const int top = static_cast<int>(mip.sizes.size());
  PENUMBRA_TRY_ASSIGN(mip.chain,
                      create_chain(format, minmax_chain_side(map_size.width, map_size.height), top,
                                   "the min-max mip"));
  for (int level = 1; level <= top; ++level) {
    const LevelSize size = mip.sizes[static_cast<std::size_t>(level - 1)];
    glCopyImageSubData(levels[static_cast<std::size_t>(level - 1)]->get(), GL_TEXTURE_2D, 0, 0, 0,
                       0, mip.chain.get(), GL_TEXTURE_2D, level - 1, 0, 0, 0, size.width,
                       size.height, 1);
    PENUMBRA_TRY(check_gl("copying min-max level " + std::to_string(level) + " into the mip"));
  }
  return mip;
}

Result<std::vector<FloatImage>> read_minmax_mip(const MinmaxMip& mip) {
  std::vector<FloatImage> levels;
  for (std::size_t m = 0; m < mip.sizes.size(); ++m) {
    auto level = read_texture(mip.chain, *mip.format, static_cast<int>(m), mip.sizes[m].width,
                              mip.sizes[m].height, "min-max level " + std::to_string(m + 1));
    if (!level) return level.error();
    levels.push_back(std::move(*level));
  }
  return levels;
}

}  // namespace penumbra::gl
