#include "query_pass.hpp"

#include <array>
#include <optional>
#include <string>

#include "full_screen_draw.hpp"
#include "minmax_mip.hpp"
#include "pass_program.hpp"
#include "textures.hpp"

namespace penumbra::gl {
namespace {

// The mip when the linked query reads shadow_minmax, else nothing: only
// what the driver reports active decides, so passes given to a query that
// does not need them are neither required nor compiled.
Result<std::optional<MinmaxMip>> minmax_for(const PassProgram& query,
                                            const SamplerObjects& samplers,
                                            const QueryInputs& inputs, const Texture& depth) {
  if (!query.reads("shadow_minmax")) return std::optional<MinmaxMip>();
  if (!inputs.passes.minmax) {
    return make_error(Error::Kind::bad_input, std::string(kQueryPass.where),
                      "the query reads shadow_minmax, the shadow map's min-max mip, but no "
                      "minmax_init and minmax_reduce passes were given to build it");
  }
  auto mip = build_minmax_mip(samplers, *inputs.passes.minmax, depth,
                              {inputs.normalized_depth.width, inputs.normalized_depth.height},
                              inputs.params);
  if (!mip) return mip.error();
  return std::optional<MinmaxMip>(std::move(*mip));
}

// One channel of a two-channel image.
FloatImage channel(const FloatImage& image, int c) {
  FloatImage out(image.width, image.height, 1);
  for (std::size_t i = 0; i < out.data.size(); ++i) out.data[i] = image.data[2 * i + c];
  return out;
}

}  // namespace

Result<GlQueryOutput> run_query_pass(const SamplerObjects& samplers, const QueryInputs& inputs) {
  PENUMBRA_TRY(check_query_inputs(inputs.normalized_depth, inputs.receivers));
  const GlPass& text = inputs.passes.query;
  auto query = prepare_pass(text.vert, text.frag, kQueryPass);
  if (!query) return query.error();
  auto depth = upload_depth(inputs.normalized_depth);
  if (!depth) return depth.error();
  auto mip = minmax_for(*query, samplers, inputs, *depth);
  if (!mip) return mip.error();
  auto receivers = upload_receivers(inputs.receivers);
  if (!receivers) return receivers.error();
  const int width = inputs.receivers.width;
  const int height = inputs.receivers.height;
  const std::string what = "the query pass";
  auto target = create_rg_target(width, height, "the target of " + what);
  if (!target) return target.error();

  // The depth texture goes to shadow_depth and shadow_cmp, each with its own
  // sampler object.
  const std::array sources = {
      ImageSource{"shadow_depth", depth->get(), samplers.point},
      ImageSource{"shadow_cmp", depth->get(), samplers.compare},
      ImageSource{"receivers", receivers->get(), samplers.point},
      ImageSource{"shadow_minmax", *mip ? (*mip)->chain.get() : 0u, samplers.mip},
  };
  PENUMBRA_TRY(draw_full_screen(*query, inputs.params, sources, {*target, width, height}, what));
  auto output = read_rg(*target, 0, width, height, what + "'s target");
  if (!output) return output.error();
  return GlQueryOutput{channel(*output, 0), channel(*output, 1)};
}

}  // namespace penumbra::gl
