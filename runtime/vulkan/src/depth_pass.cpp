#include "depth_pass.hpp"

#include <optional>
#include <string>
#include <vector>

#include "formats.hpp"
#include "pass.hpp"
#include "penumbra/model/map_encoding.hpp"

namespace penumbra::detail {

Result<std::unique_ptr<ShadowMapImages>> render_depth(
    Context& context, const PassProgram& program, std::span<const std::array<float, 3>> triangles,
    int width, int height, const ParamBlock& params, DepthFormat depth_format) {
  if (triangles.size() % 3 != 0) {
    return make_error(Error::Kind::bad_input, "depth pass",
                      std::to_string(triangles.size()) +
                          " vertices are not a whole number of triangles (a triangle list)");
  }
  auto images = create_shadow_map_images(context, width, height, depth_format);
  if (!images) return images.error();

  std::vector<float> positions;
  positions.reserve(triangles.size() * 3);
  for (const auto& vertex : triangles)
    positions.insert(positions.end(), vertex.begin(), vertex.end());

  PassDraw draw;
  draw.program = &program;
  // A linear map's depth is the shader's; an engine's hardware depth is the
  // rasterizer's (the reflection's map_encoding).
  const MapEncoding encoding = program.reflection.map_encoding.value_or(MapEncoding::linear);
  draw.shape = {"depth pass",
                kMapColourTarget,
                kDepthPositionFormat,
                3,
                true,
                encoding == MapEncoding::linear,
                !depth_increases(encoding)};
  draw.resources.params = &params;
  draw.positions = positions;
  // The output 0 and the fragment depth both hold normalized depth; each
  // image ends in its resting layout, where every later use starts.
  draw.target.colour = &(*images)->colour;
  draw.target.colour_final = kMapColourLayout;
  draw.target.depth = &(*images)->depth;
  draw.target.depth_final = kMapDepthLayout;
  draw.target.next_stages = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
  draw.target.next_access = VK_ACCESS_SHADER_READ_BIT;
  auto drawn = draw_pass(context, draw);
  if (!drawn) return drawn.error();
  (*images)->depth_gpu_ms = *drawn;
  return std::move(*images);
}

}  // namespace penumbra::detail
