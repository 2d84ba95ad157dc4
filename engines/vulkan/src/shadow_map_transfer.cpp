#include "shadow_map_transfer.hpp"

#include <utility>

#include "image_transfer.hpp"
#include "penumbra/support/image_checks.hpp"

namespace penumbra::detail {

Result<std::unique_ptr<ShadowMapImages>> upload_shadow_map(Context& context,
                                                           const FloatImage& normalized_depth) {
  PENUMBRA_TRY(check_normalized_depth(normalized_depth));
  auto images = create_shadow_map_images(context, normalized_depth.width, normalized_depth.height);
  if (!images) return images.error();
  PENUMBRA_TRY(upload_image(*context.device, *context.commands, (*images)->depth,
                            normalized_depth.data, kMapDepthLayout,
                            "the shadow map's depth image"));
  PENUMBRA_TRY(upload_image(*context.device, *context.commands, (*images)->colour,
                            normalized_depth.data, kMapColourLayout,
                            "the shadow map's colour image"));
  return std::move(*images);
}

Result<FloatImage> read_shadow_map(Context& context, const ShadowMapImages& map) {
  auto texels = read_image(*context.device, *context.commands, map.colour, kMapColourLayout, 1,
                           "the shadow map's colour image");
  if (!texels) return texels.error();
  FloatImage image(static_cast<int>(map.colour.desc().width),
                   static_cast<int>(map.colour.desc().height), 1);
  image.data = std::move(*texels);
  return image;
}

}  // namespace penumbra::detail
