#include "screen_blur_chain.hpp"

#include <string>
#include <utility>

#include "full_screen_draw.hpp"
#include "pass_program.hpp"
#include "penumbra/support/image_checks.hpp"
#include "penumbra/support/minmax_levels.hpp"
#include "query_pass.hpp"
#include "textures.hpp"

namespace penumbra::gl {
namespace {

struct ChainPrograms {
  PassProgram query;
  PassProgram blur_h;
  PassProgram blur_v;
  PassProgram composite;
};

Result<ChainPrograms> prepare_chain(const GlScreenBlurPasses& passes) {
  auto query = prepare_pass(passes.query, PassKind::query);
  if (!query) return query.error();
  auto blur_h = prepare_pass(passes.blur_h, PassKind::blur_h);
  if (!blur_h) return blur_h.error();
  auto blur_v = prepare_pass(passes.blur_v, PassKind::blur_v);
  if (!blur_v) return blur_v.error();
  auto composite = prepare_pass(passes.composite, PassKind::composite);
  if (!composite) return composite.error();
  return ChainPrograms{std::move(*query), std::move(*blur_h), std::move(*blur_v),
                       std::move(*composite)};
}

// Channel 0 of a blur pass's screen-sized target.
Result<FloatImage> read_factor(const PassProgram& pass, const Texture& target,
                               const FloatImage& screen) {
  auto texels = read_texture(target, *pass.target_format, 0, screen.width, screen.height,
                             "the " + pass.where + "'s target");
  if (!texels) return texels.error();
  return channel(*texels, 0);
}

}  // namespace

Result<GlScreenBlurOutput> run_screen_blur_chain(const GlScreenBlurPasses& passes,
                                                 const ScreenBlurInputs& inputs) {
  PENUMBRA_TRY(check_query_inputs(inputs.normalized_depth, inputs.receivers));
  PENUMBRA_TRY(check_scene_colour(inputs.scene_colour, inputs.receivers));
  auto programs = prepare_chain(passes);
  if (!programs) return programs.error();
  const FloatImage& screen = inputs.receivers;
  ParamBlock screen_params = inputs.params;
  screen_params["screen_size"] = size_vec4(screen.width, screen.height);
  const QueryInputs query_images{inputs.normalized_depth, inputs.receivers, screen_params,
                                 DepthFormat::d32_float};
  PassInputs textures;
  give_query_images(textures, query_images);
  textures.give(TextureId::scene_colour, inputs.scene_colour);

  auto factor = draw_query(programs->query, std::nullopt, textures, query_images);
  if (!factor) return factor.error();
  // Each later pass reads the previous pass's target as screen_factor.
  const auto draw_next = [&](const PassProgram& pass, const PassProgram& previous,
                             const Texture& source) -> Result<Texture> {
    textures.set(TextureId::screen_factor, source.get(), *previous.target_format,
                 "the " + previous.where + "'s target");
    const std::string what = "the " + pass.where;
    auto target = create_pass_target(pass, screen.width, screen.height, "the target of " + what);
    if (!target) return target.error();
    PENUMBRA_TRY(draw_full_screen(pass, screen_params, textures,
                                  {*target, screen.width, screen.height}, what));
    return std::move(*target);
  };
  auto blurred_h = draw_next(programs->blur_h, programs->query, *factor);
  if (!blurred_h) return blurred_h.error();
  auto blurred_v = draw_next(programs->blur_v, programs->blur_h, *blurred_h);
  if (!blurred_v) return blurred_v.error();
  auto composite = draw_next(programs->composite, programs->blur_v, *blurred_v);
  if (!composite) return composite.error();

  auto factor_texels = read_texture(*factor, *programs->query.target_format, 0, screen.width,
                                    screen.height, "the query pass's target");
  if (!factor_texels) return factor_texels.error();
  auto h = read_factor(programs->blur_h, *blurred_h, screen);
  if (!h) return h.error();
  auto v = read_factor(programs->blur_v, *blurred_v, screen);
  if (!v) return v.error();
  auto colour = read_texture(*composite, *programs->composite.target_format, 0, screen.width,
                             screen.height, "the composite pass's target");
  if (!colour) return colour.error();
  return GlScreenBlurOutput{channel(*factor_texels, 0), channel(*factor_texels, 1), std::move(*h),
                            std::move(*v), std::move(*colour)};
}

}  // namespace penumbra::gl
