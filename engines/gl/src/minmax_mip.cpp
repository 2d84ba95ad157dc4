#include "minmax_mip.hpp"

#include <string>

#include "full_screen_draw.hpp"
#include "gl_check.hpp"
#include "pass_program.hpp"
#include "penumbra/support/minmax_levels.hpp"
#include "textures.hpp"

namespace penumbra::gl {

// The chain is 2^(N-1) square, as in the Vulkan runtime (minmax_chain_side
// in penumbra/support/minmax_levels.hpp says why). No level is ever drawn
// while it is sampled: each is drawn into its own texture, which the next
// reduce pass reads and glCopyImageSubData copies into the chain.
Result<MinmaxMip> build_minmax_mip(const GlMinmaxPasses& passes, PassInputs& inputs,
                                   LevelSize map_size, const ParamBlock& params) {
  auto init = prepare_pass(passes.init, PassKind::minmax_init);
  if (!init) return init.error();
  auto reduce = prepare_pass(passes.reduce, PassKind::minmax_reduce);
  if (!reduce) return reduce.error();
  if (init->target_format != reduce->target_format) {
    return make_error(Error::Kind::bad_input, reduce->where,
                      "its render target is " + std::string(reduce->target_format->name()) +
                          " but the minmax_init pass's is " +
                          std::string(init->target_format->name()) +
                          "; both draw levels of one mip");
  }
  MinmaxMip mip;
  mip.format = init->target_format;
  mip.sizes = minmax_level_sizes(map_size.width, map_size.height);
  const int levels = static_cast<int>(mip.sizes.size());
  auto chain = create_chain(*mip.format, minmax_chain_side(map_size.width, map_size.height), levels,
                            "the min-max mip");
  if (!chain) return chain.error();
  mip.chain = std::move(*chain);

  Texture source_level;
  LevelSize source = map_size;
  for (int level = 1; level <= levels; ++level) {
    const LevelSize size = mip.sizes[static_cast<std::size_t>(level - 1)];
    const PassProgram& pass = level == 1 ? *init : *reduce;
    const std::string what = "the " + pass.where + " (min-max level " + std::to_string(level) + ")";
    auto target = create_pass_target(pass, size.width, size.height, "the target of " + what);
    if (!target) return target.error();
    ParamBlock level_params = params;
    level_params["source_size"] = size_vec4(source.width, source.height);
    level_params["screen_size"] = size_vec4(size.width, size.height);
    if (level > 1) {
      inputs.set(TextureId::minmax_source, source_level.get(), *mip.format,
                 "min-max level " + std::to_string(level - 1));
    }
    PENUMBRA_TRY(
        draw_full_screen(pass, level_params, inputs, {*target, size.width, size.height}, what));
    glCopyImageSubData(target->get(), GL_TEXTURE_2D, 0, 0, 0, 0, mip.chain.get(), GL_TEXTURE_2D,
                       level - 1, 0, 0, 0, size.width, size.height, 1);
    PENUMBRA_TRY(check_gl("copying " + what + " into the min-max mip"));
    source_level = std::move(*target);
    source = size;
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

Result<std::optional<MinmaxMip>> give_minmax_mip(const PassProgram& pass,
                                                 const std::optional<GlMinmaxPasses>& minmax,
                                                 PassInputs& inputs, LevelSize map_size,
                                                 const ParamBlock& params) {
  // Only what the driver reports active decides, so passes given to a
  // program that does not read the mip are neither required nor compiled.
  if (!pass.reads(TextureId::shadow_minmax)) return std::optional<MinmaxMip>{};
  if (!minmax) {
    return make_error(Error::Kind::bad_input, pass.where,
                      "it reads shadow_minmax, the shadow map's min-max mip, but no "
                      "minmax_init and minmax_reduce passes were given to build it");
  }
  PENUMBRA_TRY_ASSIGN(MinmaxMip mip, build_minmax_mip(*minmax, inputs, map_size, params));
  inputs.set(TextureId::shadow_minmax, mip.chain.get(), *mip.format, "the min-max mip");
  return std::optional<MinmaxMip>(std::move(mip));
}

}  // namespace penumbra::gl
