#include "query_pass.hpp"

#include <functional>
#include <string>
#include <utility>

#include "formats.hpp"
#include "image_transfer.hpp"
#include "pass.hpp"
#include "penumbra/support/full_screen_triangle.hpp"
#include "penumbra/support/image_checks.hpp"
#include "reflection_binding.hpp"
#include "shadow_map_transfer.hpp"

namespace penumbra::detail {

Result<vk::Image> upload_receivers(Context& context, const FloatImage& receivers) {
  PENUMBRA_TRY(check_receivers(receivers));
  PENUMBRA_TRY(context.check_extent(receivers.width, receivers.height, "receivers"));
  auto image = vk::Image::create(
      *context.device,
      {static_cast<std::uint32_t>(receivers.width), static_cast<std::uint32_t>(receivers.height),
       kReceiversFormat, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
       VK_IMAGE_ASPECT_COLOR_BIT},
      "the receivers image");
  if (!image) return image.error();
  PENUMBRA_TRY(upload_image(*context.device, *context.commands, *image,
                            receivers_to_rgba(receivers), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                            "the receivers image"));
  return std::move(*image);
}

namespace {

// `program` over one full-screen triangle into a width x height
// R32G32_SFLOAT target, reading the map and what `offer` adds: the query
// and the deferred pass differ only in their per-pixel input.
Result<QueryOutput> draw_visibility(Context& context, const PassProgram& program,
                                    const ShadowMapImages& map, int width, int height,
                                    const ParamBlock& params, const char* what,
                                    const std::function<void(PassResources&)>& offer) {
  // Said here rather than as "nothing to bind": the map could have one.
  if (!map.minmax && reads_texture(program.reflection, TextureId::shadow_minmax)) {
    return make_error(Error::Kind::bad_input, what,
                      "the program reads shadow_minmax, the shadow map's min-max mip, but this " +
                          std::to_string(map.colour.desc().width) + "x" +
                          std::to_string(map.colour.desc().height) +
                          " map has none; build it first (Engine::build_minmax with the "
                          "variant's minmax_init and minmax_reduce passes)");
  }
  auto visibility = vk::Image::create(
      *context.device,
      {static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), kVisibilityFormat,
       VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
       VK_IMAGE_ASPECT_COLOR_BIT},
      "the visibility image");
  if (!visibility) return visibility.error();

  PassDraw draw;
  draw.program = &program;
  draw.shape = {what, kVisibilityTarget, kQueryPositionFormat, 2, false, false};
  draw.resources.params = &params;
  draw.resources.offer_map(map, /*comparison=*/true);
  offer(draw.resources);
  draw.positions = kFullScreenTriangle;
  draw.target.colour = &*visibility;
  draw.target.colour_final = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  draw.target.next_stages = VK_PIPELINE_STAGE_TRANSFER_BIT;
  draw.target.next_access = VK_ACCESS_TRANSFER_READ_BIT;
  auto elapsed = draw_pass(context, draw);
  if (!elapsed) return elapsed.error();

  QueryOutput output;
  output.gpu_ms = *elapsed;
  auto texels = read_image(*context.device, *context.commands, *visibility,
                           VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, 2, "the visibility image");
  if (!texels) return texels.error();
  output.visibility = FloatImage(width, height, 1);
  output.texel_reads = FloatImage(width, height, 1);
  for (std::size_t p = 0; p < output.visibility.pixel_count(); ++p) {
    output.visibility.data[p] = (*texels)[2 * p];
    output.texel_reads.data[p] = (*texels)[2 * p + 1];
  }
  return output;
}

}  // namespace

Result<QueryOutput> run_query(Context& context, const PassProgram& program,
                              const ShadowMapImages& map, const FloatImage& receivers,
                              const ParamBlock& params) {
  auto receivers_image = upload_receivers(context, receivers);
  if (!receivers_image) return receivers_image.error();
  return draw_visibility(context, program, map, receivers.width, receivers.height, params,
                         "query pass", [&](PassResources& resources) {
                           resources.offer(TextureId::receivers, *receivers_image,
                                           VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
                         });
}

Result<QueryOutput> run_deferred(Context& context, const PassProgram& program,
                                 const ShadowMapImages& map, const FloatImage& camera_depth,
                                 const ParamBlock& params) {
  // Images like the map's, written from the host as an engine's depth pass
  // would have: a depth image, and the R32F twin a Direct3D 9 engine draws.
  auto camera = upload_shadow_map(context, camera_depth);
  if (!camera) return camera.error();
  return draw_visibility(
      context, program, map, camera_depth.width, camera_depth.height, params, "deferred pass",
      [&](PassResources& resources) {
        resources.offer(TextureId::camera_depth, (*camera)->depth, kMapDepthLayout);
        resources.offer(TextureId::camera_depth, (*camera)->colour, kMapColourLayout);
      });
}

}  // namespace penumbra::detail
