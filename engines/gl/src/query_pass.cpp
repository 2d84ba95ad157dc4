#include "query_pass.hpp"

#include <string>

#include "full_screen_draw.hpp"
#include "minmax_mip.hpp"
#include "penumbra/support/image_checks.hpp"
#include "textures.hpp"

namespace penumbra::gl {

void give_query_images(PassInputs& inputs, const QueryInputs& images) {
  inputs.give(TextureId::shadow_depth, images.normalized_depth, images.map_format);
  inputs.give(TextureId::shadow_cmp, images.normalized_depth, images.map_format);
  inputs.give(TextureId::receivers, images.receivers);
}

Result<Texture> draw_query(const PassProgram& query, const std::optional<GlMinmaxPasses>& minmax,
                           PassInputs& inputs, const QueryInputs& images) {
  if (query.target_format->channels < 2) {
    return make_error(Error::Kind::bad_input, query.where,
                      "its render target is " + std::string(query.target_format->name()) +
                          "; the query writes (visibility, texel reads), two channels");
  }
  PENUMBRA_TRY_ASSIGN(
      const std::optional<MinmaxMip> mip,
      give_minmax_mip(query, minmax, inputs,
                      {images.normalized_depth.width, images.normalized_depth.height},
                      images.params));
  const int width = images.receivers.width;
  const int height = images.receivers.height;
  const std::string what = "the " + query.where;
  auto target = create_pass_target(query, width, height, "the target of " + what);
  if (!target) return target.error();
  PENUMBRA_TRY(draw_full_screen(query, images.params, inputs, {*target, width, height}, what));
  return std::move(*target);
}

Result<GlQueryOutput> run_query_pass(const GlQueryPasses& passes, const QueryInputs& images) {
  PENUMBRA_TRY(check_query_inputs(images.normalized_depth, images.receivers));
  auto query = prepare_pass(passes.query, PassKind::query);
  if (!query) return query.error();
  PassInputs inputs;
  give_query_images(inputs, images);
  auto target = draw_query(*query, passes.minmax, inputs, images);
  if (!target) return target.error();
  auto output = read_texture(*target, *query->target_format, 0, images.receivers.width,
                             images.receivers.height, "the query pass's target");
  if (!output) return output.error();
  return GlQueryOutput{channel(*output, 0), channel(*output, 1)};
}

Result<GlQueryOutput> run_deferred_pass(const GlPass& pass, const FloatImage& normalized_depth,
                                        const FloatImage& camera_depth, const ParamBlock& params,
                                        DepthFormat map_format,
                                        const std::optional<GlMinmaxPasses>& minmax) {
  PENUMBRA_TRY(check_shadow_map(normalized_depth));
  PENUMBRA_TRY(check_shadow_map(camera_depth));
  auto deferred = prepare_pass(pass, PassKind::deferred);
  if (!deferred) return deferred.error();
  PassInputs inputs;
  inputs.give(TextureId::shadow_depth, normalized_depth, map_format);
  inputs.give(TextureId::shadow_cmp, normalized_depth, map_format);
  // Uploaded in the binding's format: a depth texture, as the engine's
  // camera drew it.
  inputs.give(TextureId::camera_depth, camera_depth);
  PENUMBRA_TRY_ASSIGN(const std::optional<MinmaxMip> mip,
                      give_minmax_mip(*deferred, minmax, inputs,
                                      {normalized_depth.width, normalized_depth.height}, params));
  const int width = camera_depth.width;
  const int height = camera_depth.height;
  const std::string what = "the " + deferred->where;
  auto target = create_pass_target(*deferred, width, height, "the target of " + what);
  if (!target) return target.error();
  PENUMBRA_TRY(draw_full_screen(*deferred, params, inputs, {*target, width, height}, what));
  auto output = read_texture(*target, *deferred->target_format, 0, width, height,
                             "the deferred pass's target");
  if (!output) return output.error();
  return GlQueryOutput{channel(*output, 0), channel(*output, 1)};
}

}  // namespace penumbra::gl
