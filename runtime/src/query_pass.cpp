#include "query_pass.hpp"

#include "formats.hpp"
#include "image_transfer.hpp"
#include "pass.hpp"
#include "penumbra/support/full_screen_triangle.hpp"
#include "penumbra/support/image_checks.hpp"

namespace penumbra::detail {

Result<FloatImage> run_query(Context& context, const PassProgram& program,
                             const ShadowMapImages& map, const FloatImage& receivers,
                             const ParamBlock& params) {
  PENUMBRA_TRY(check_receivers(receivers));
  PENUMBRA_TRY(context.check_extent(receivers.width, receivers.height, "receivers"));
  const auto width = static_cast<std::uint32_t>(receivers.width);
  const auto height = static_cast<std::uint32_t>(receivers.height);

  auto receivers_image = vk::Image::create(
      *context.device,
      {width, height, kReceiversFormat,
       VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_IMAGE_ASPECT_COLOR_BIT},
      "the receivers image");
  if (!receivers_image) return receivers_image.error();
  PENUMBRA_TRY(upload_image(*context.device, *context.commands, *receivers_image,
                            receivers_to_rgba(receivers), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                            "the receivers image"));
  auto visibility =
      vk::Image::create(*context.device,
                        {width, height, kVisibilityFormat,
                         VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                         VK_IMAGE_ASPECT_COLOR_BIT},
                        "the visibility image");
  if (!visibility) return visibility.error();

  PassDraw draw;
  draw.program = &program;
  draw.shape = {"query pass", kQueryPositionFormat, 2, false, false};
  draw.resources = {&params, &map, &*receivers_image};
  draw.positions = kFullScreenTriangle;
  draw.target.colour = &*visibility;
  draw.target.colour_final = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  draw.target.next_stages = VK_PIPELINE_STAGE_TRANSFER_BIT;
  draw.target.next_access = VK_ACCESS_TRANSFER_READ_BIT;
  PENUMBRA_TRY(draw_pass(context, draw));

  auto texels = read_image(*context.device, *context.commands, *visibility,
                           VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, 1, "the visibility image");
  if (!texels) return texels.error();
  FloatImage result(receivers.width, receivers.height, 1);
  result.data = std::move(*texels);
  return result;
}

}  // namespace penumbra::detail
