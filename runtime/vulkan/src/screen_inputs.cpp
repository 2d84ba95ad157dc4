#include "screen_inputs.hpp"

#include <string>
#include <utility>

#include "formats.hpp"
#include "image_transfer.hpp"
#include "penumbra/support/image_checks.hpp"

namespace penumbra::detail {
namespace {

Result<vk::Image> upload_rgba(Context& context, const FloatImage& image,
                              std::span<const float> rgba, const std::string& what) {
  PENUMBRA_TRY(context.check_extent(image.width, image.height, what));
  PENUMBRA_TRY_ASSIGN(
      vk::Image uploaded,
      vk::Image::create(
          *context.device,
          {static_cast<std::uint32_t>(image.width), static_cast<std::uint32_t>(image.height),
           kReceiversFormat, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
           VK_IMAGE_ASPECT_COLOR_BIT},
          "the " + what + " image"));
  PENUMBRA_TRY(upload_image(*context.device, *context.commands, uploaded, rgba,
                            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, "the " + what + " image"));
  return uploaded;
}

}  // namespace

Result<vk::Image> upload_receivers(Context& context, const FloatImage& receivers) {
  PENUMBRA_TRY(check_receivers(receivers));
  return upload_rgba(context, receivers, receivers_to_rgba(receivers), "receivers");
}

Result<vk::Image> upload_scene_colour(Context& context, const FloatImage& scene_colour) {
  if (scene_colour.channels != 4) {
    return make_error(
        Error::Kind::bad_input, "scene colour",
        "expected four channels (RGBA), got " + std::to_string(scene_colour.channels));
  }
  return upload_rgba(context, scene_colour, scene_colour.data, "scene colour");
}

}  // namespace penumbra::detail
