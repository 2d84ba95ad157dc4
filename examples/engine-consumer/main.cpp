// engine_consumer [OUT.png]: soft shadows as an engine draws them with
// Penumbra on Vulkan. The PCSS shaders are compiled into this program
// (engine_shadows, generated from shadows.json at build time). A box stands
// on the ground under a square area light; the depth pass renders the box
// into a shadow map, the PCSS query pass shades every pixel of the ground,
// and the ground's visibility is written as a greyscale PNG (white: lit,
// black: the umbra), by default shadow.png.
#include <png.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "engine_shadows/shaders.hpp"
#include "penumbra/model/light.hpp"
#include "penumbra/model/shadow_params.hpp"
#include "penumbra/vulkan/embedded_program.hpp"
#include "penumbra/vulkan/engine.hpp"
#include "scene.hpp"

namespace {

using namespace scene;

// What the query pass reads per pixel: the point the pixel shows as (u, v)
// in the shadow map and its light-view depth z. An engine computes it from
// each pixel's position; here the picture looks straight down at the ground.
penumbra::FloatImage ground_receivers(const penumbra::LightParams& light) {
  // The ground x (or y) at the centre of pixel column i (or row j).
  const auto at = [](int pixel) {
    return (2.0 * (pixel + 0.5) / kImageSize - 1.0) * kGroundHalfWidth;
  };
  penumbra::FloatImage receivers(kImageSize, kImageSize, 3);
  for (int j = 0; j < kImageSize; ++j) {
    for (int i = 0; i < kImageSize; ++i) {
      const auto uv = penumbra::project(light, at(i), at(j), kGroundZ);
      receivers.at(i, j, 0) = static_cast<float>(uv.u);
      receivers.at(i, j, 1) = static_cast<float>(uv.v);
      receivers.at(i, j, 2) = kGroundZ;
    }
  }
  return receivers;
}

// libpng's simplified API: 8-bit grey, row 0 at the top.
bool write_png(const std::string& path, const penumbra::FloatImage& visibility) {
  std::vector<png_byte> pixels;
  for (float v : visibility.data) {
    pixels.push_back(static_cast<png_byte>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)));
  }
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(visibility.width);
  image.height = static_cast<png_uint_32>(visibility.height);
  image.format = PNG_FORMAT_GRAY;
  return png_image_write_to_file(&image, path.c_str(), 0, pixels.data(), 0, nullptr) != 0;
}

int fail(const std::string& message) {
  std::fprintf(stderr, "engine_consumer: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "shadow.png";

  // The shaders: PCSS with 16 blocker-search and 16 filter samples on the
  // whitepaper's Poisson disk, its depth and query passes for Vulkan.
  const penumbra::VariantKeys keys{
      .blocker_samples = 16, .pcf_samples = 16, .disk = "whitepaper16"};
  const penumbra::shaders::Program* depth_code = engine_shadows::find(
      penumbra::Technique::pcss, keys, penumbra::Target::spirv, penumbra::PassKind::depth);
  const penumbra::shaders::Program* query_code =
      engine_shadows::find(penumbra::Technique::pcss, keys, penumbra::Target::spirv);
  if (depth_code == nullptr || query_code == nullptr) {
    return fail("shadows.json does not build this pcss variant for spirv");
  }
  auto depth = penumbra::embedded_program(*depth_code);
  if (!depth) return fail(depth.error().to_string());
  auto query = penumbra::embedded_program(*query_code);
  if (!query) return fail(query.error().to_string());

  // The device: lavapipe when present, else the first one.
  auto engine = penumbra::Engine::create({}, [](const penumbra::Diagnostic& d) {
    if (d.severity != penumbra::Severity::note) std::fprintf(stderr, "%s\n", d.message.c_str());
  });
  if (!engine) return fail(engine.error().to_string());

  // The light and the shadow map's frustum. Depths up to z = 32 are stored
  // in [0, 1], scaled by a power of two (exact). Every pass takes its values
  // from this one block.
  penumbra::LightParams light;
  light.light_world_size = kLightSize;
  light.frustum_width = kFrustumWidth;
  light.near_plane = kNear;
  const penumbra::ParamBlock params = penumbra::shadow_params(
      light, {kMapSize, kMapSize, kImageSize, kImageSize}, penumbra::depth_scale_for(kFar));

  // Pass 1: the box, seen from the light, into the shadow map. The ground
  // only receives, so it is not drawn (and needs no depth bias).
  auto map = (*engine)->render_depth(*depth, box_triangles(), kMapSize, kMapSize, params);
  if (!map) return fail(map.error().to_string());
  // Pass 2: the PCSS query for every pixel of the ground.
  auto visibility = (*engine)->run_query(*query, **map, ground_receivers(light), params);
  if (!visibility) return fail(visibility.error().to_string());

  if (!write_png(out, *visibility)) return fail("cannot write " + out);
  const auto penumbra_pixels =
      std::ranges::count_if(visibility->data, [](float v) { return v > 0.0f && v < 1.0f; });
  std::printf("engine_consumer: %s on %s: wrote %s (%dx%d, %td pixels in the penumbra)\n",
              std::string(query_code->variant).c_str(), (*engine)->device_info().name.c_str(),
              out.c_str(), kImageSize, kImageSize, penumbra_pixels);
  return 0;
}
