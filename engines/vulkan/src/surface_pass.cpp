#include "surface_pass.hpp"

#include <string>
#include <utility>
#include <vector>

#include "formats.hpp"
#include "image_transfer.hpp"
#include "pass.hpp"

namespace penumbra::detail {

Result<FloatImage> run_surface(Context& context, const PassProgram& program,
                               std::span<const std::array<float, 3>> triangles,
                               const ShadowMapImages& map, int width, int height,
                               const ParamBlock& params) {
  if (triangles.size() % 3 != 0) {
    return make_error(Error::Kind::bad_input, "surface pass",
                      std::to_string(triangles.size()) +
                          " vertices are not a whole number of triangles (a triangle list)");
  }
  PENUMBRA_TRY(context.check_extent(width, height, "surface pass"));
  const auto w = static_cast<std::uint32_t>(width);
  const auto h = static_cast<std::uint32_t>(height);
  auto colour =
      vk::Image::create(*context.device,
                        {w, h, kCompositeFormat,
                         VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                         VK_IMAGE_ASPECT_COLOR_BIT},
                        "the surface pass's colour image");
  if (!colour) return colour.error();
  // The camera's own depth buffer: the nearest surface wins, as in an engine.
  auto depth =
      vk::Image::create(*context.device,
                        {w, h, kMapDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                         VK_IMAGE_ASPECT_DEPTH_BIT},
                        "the surface pass's depth image");
  if (!depth) return depth.error();

  std::vector<float> positions;
  positions.reserve(triangles.size() * 3);
  for (const auto& vertex : triangles) {
    positions.insert(positions.end(), vertex.begin(), vertex.end());
  }
  PassDraw draw;
  draw.program = &program;
  draw.shape = {"surface pass", kCompositeTarget, kDepthPositionFormat, 3, true, false, false};
  draw.resources.params = &params;
  draw.resources.offer_map(map, /*comparison=*/true);
  draw.positions = positions;
  draw.target.colour = &*colour;
  draw.target.colour_final = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  draw.target.depth = &*depth;
  draw.target.depth_final = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  draw.target.next_stages = VK_PIPELINE_STAGE_TRANSFER_BIT;
  draw.target.next_access = VK_ACCESS_TRANSFER_READ_BIT;
  auto drawn = draw_pass(context, draw);
  if (!drawn) return drawn.error();

  auto texels =
      read_image(*context.device, *context.commands, *colour, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                 4, "the surface pass's colour image");
  if (!texels) return texels.error();
  FloatImage out(width, height, 4);
  out.data = std::move(*texels);
  return out;
}

}  // namespace penumbra::detail
