#include "screen_blur_chain.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "formats.hpp"
#include "image_transfer.hpp"
#include "pass.hpp"
#include "penumbra/support/full_screen_triangle.hpp"
#include "penumbra/support/minmax_levels.hpp"
#include "query_pass.hpp"

namespace penumbra::detail {
namespace {

// Where every image the chain samples rests.
constexpr VkImageLayout kRead = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;

Status check_scene_colour(const FloatImage& scene_colour, const FloatImage& receivers) {
  if (scene_colour.channels != 4) {
    return make_error(
        Error::Kind::bad_input, "scene colour",
        "expected four channels (RGBA), got " + std::to_string(scene_colour.channels));
  }
  if (scene_colour.width != receivers.width || scene_colour.height != receivers.height) {
    return make_error(Error::Kind::bad_input, "scene colour",
                      "is " + std::to_string(scene_colour.width) + "x" +
                          std::to_string(scene_colour.height) + " but the screen (receivers) is " +
                          std::to_string(receivers.width) + "x" + std::to_string(receivers.height));
  }
  return {};
}

Result<vk::Image> upload_scene_colour(Context& context, const FloatImage& scene_colour) {
  auto image = vk::Image::create(
      *context.device,
      {static_cast<std::uint32_t>(scene_colour.width),
       static_cast<std::uint32_t>(scene_colour.height), kSceneColourFormat,
       VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_IMAGE_ASPECT_COLOR_BIT},
      "the scene colour image");
  if (!image) return image.error();
  PENUMBRA_TRY(upload_image(*context.device, *context.commands, *image, scene_colour.data,
                            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, "the scene colour image"));
  return std::move(*image);
}

// A pass's screen-sized target, sampled by the next pass and read back.
Result<vk::Image> create_target(const Context& context, const FloatImage& screen, VkFormat format,
                                const std::string& what) {
  return vk::Image::create(
      *context.device,
      {static_cast<std::uint32_t>(screen.width), static_cast<std::uint32_t>(screen.height), format,
       VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
           VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
       VK_IMAGE_ASPECT_COLOR_BIT},
      what);
}

// Draws one pass of the chain into `target`, left in SHADER_READ_ONLY_OPTIMAL
// for the next pass and the readback, adding its GPU time to `gpu_ms`.
Status draw_chain_pass(Context& context, const PassProgram& program, std::string_view name,
                       ColourTarget shape_target, const PassResources& resources,
                       const vk::Image& target, std::optional<double>& gpu_ms) {
  PassDraw draw;
  draw.program = &program;
  draw.shape = {name, shape_target, kQueryPositionFormat, 2, false, false};
  draw.resources = resources;
  draw.positions = kFullScreenTriangle;
  draw.target = sampled_target(target);
  auto elapsed = draw_pass(context, draw);
  if (!elapsed) return elapsed.error();
  add_gpu_time(gpu_ms, *elapsed);
  return {};
}

// Component `component` of every texel of a `components`-wide target.
Result<FloatImage> read_channel(Context& context, const vk::Image& target, std::uint32_t components,
                                std::uint32_t component, std::string_view what) {
  auto texels = read_image(*context.device, *context.commands, target,
                           VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, components, what);
  if (!texels) return texels.error();
  const VkExtent2D extent = target.extent();
  FloatImage out(static_cast<int>(extent.width), static_cast<int>(extent.height), 1);
  for (std::size_t p = 0; p < out.pixel_count(); ++p) {
    out.data[p] = (*texels)[components * p + component];
  }
  return out;
}

}  // namespace

Result<ScreenBlurOutput> run_screen_blur(Context& context, const ScreenBlurPrograms& programs,
                                         const ShadowMapImages& map, const FloatImage& receivers,
                                         const FloatImage& scene_colour, const ParamBlock& params) {
  auto receivers_image = upload_receivers(context, receivers);
  if (!receivers_image) return receivers_image.error();
  PENUMBRA_TRY(check_scene_colour(scene_colour, receivers));
  auto colour_image = upload_scene_colour(context, scene_colour);
  if (!colour_image) return colour_image.error();

  ParamBlock screen_params = params;
  screen_params["screen_size"] = size_vec4(receivers.width, receivers.height);
  ScreenBlurOutput output;

  auto factor = create_target(context, receivers, kScreenFactorFormat, "the shadow factor image");
  if (!factor) return factor.error();
  PassResources query;
  query.params = &screen_params;
  query.offer_map(map, /*comparison=*/true);
  query.offer(TextureId::receivers, *receivers_image, kRead);
  PENUMBRA_TRY(draw_chain_pass(context, programs.query, "screen_blur query pass",
                               kScreenFactorTarget, query, *factor, output.gpu_ms));

  // Each blur pass reads the previous target as screen_factor.
  std::vector<vk::Image> blurred;
  blurred.reserve(2);  // `source` points into it
  const vk::Image* source = &*factor;
  for (const auto& [program, name] :
       {std::pair{&programs.blur_h, "blur_h pass"}, std::pair{&programs.blur_v, "blur_v pass"}}) {
    auto target = create_target(context, receivers, kScreenFactorFormat,
                                std::string("the ") + name + " target");
    if (!target) return target.error();
    PassResources blur;
    blur.params = &screen_params;
    blur.offer(TextureId::receivers, *receivers_image, kRead);
    blur.offer(TextureId::screen_factor, *source, kRead);
    PENUMBRA_TRY(draw_chain_pass(context, *program, name, kScreenFactorTarget, blur, *target,
                                 output.gpu_ms));
    blurred.push_back(std::move(*target));
    source = &blurred.back();
  }

  auto composite = create_target(context, receivers, kCompositeFormat, "the composite image");
  if (!composite) return composite.error();
  PassResources composite_resources;
  composite_resources.params = &screen_params;
  composite_resources.offer(TextureId::screen_factor, *source, kRead);
  composite_resources.offer(TextureId::scene_colour, *colour_image, kRead);
  PENUMBRA_TRY(draw_chain_pass(context, programs.composite, "composite pass", kCompositeTarget,
                               composite_resources, *composite, output.gpu_ms));

  auto factor_out = read_channel(context, *factor, 2, 0, "the shadow factor image");
  if (!factor_out) return factor_out.error();
  auto reads = read_channel(context, *factor, 2, 1, "the shadow factor image");
  if (!reads) return reads.error();
  auto blurred_h = read_channel(context, blurred[0], 2, 0, "the blur_h target");
  if (!blurred_h) return blurred_h.error();
  auto blurred_v = read_channel(context, blurred[1], 2, 0, "the blur_v target");
  if (!blurred_v) return blurred_v.error();
  auto colour = read_image(*context.device, *context.commands, *composite,
                           VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, 4, "the composite image");
  if (!colour) return colour.error();
  output.factor = std::move(*factor_out);
  output.texel_reads = std::move(*reads);
  output.blurred_h = std::move(*blurred_h);
  output.blurred = std::move(*blurred_v);
  output.composite = FloatImage(receivers.width, receivers.height, 4);
  output.composite.data = std::move(*colour);
  return output;
}

}  // namespace penumbra::detail
