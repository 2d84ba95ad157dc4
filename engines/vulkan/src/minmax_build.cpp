#include "minmax_build.hpp"

#include <string>
#include <utility>
#include <vector>

#include "formats.hpp"
#include "image_transfer.hpp"
#include "pass.hpp"
#include "penumbra/support/full_screen_triangle.hpp"
#include "penumbra/support/minmax_levels.hpp"
#include "vk/barrier.hpp"

namespace penumbra::detail {
namespace {

// The 2^(N-1) square chain that holds the levels (minmax_chain_side in
// penumbra/support/minmax_levels.hpp says why that size).
Result<vk::Image> create_chain(const Context& context, int width, int height) {
  const auto side = static_cast<std::uint32_t>(minmax_chain_side(width, height));
  const auto levels = static_cast<std::uint32_t>(minmax_top_level(width, height));
  return vk::Image::create(*context.device,
                           {side, side, kMinmaxFormat,
                            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                            VK_IMAGE_ASPECT_COLOR_BIT, levels},
                           "the min-max mip");
}

// One level drawn by its pass into a target of its own, which the next
// reduce pass reads as minmax_source and the chain copies from.
Result<vk::Image> create_level_target(const Context& context, LevelSize size, int level) {
  return vk::Image::create(*context.device,
                           {static_cast<std::uint32_t>(size.width),
                            static_cast<std::uint32_t>(size.height), kMinmaxFormat,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                            VK_IMAGE_ASPECT_COLOR_BIT},
                           "min-max level " + std::to_string(level));
}

// The chain: padding cleared to 1.0 (the far plane, as the map's clear), each
// level copied in, then at rest for sampling.
void record_chain_copies(VkCommandBuffer cmd, const vk::Image& chain,
                         const std::vector<vk::Image>& levels) {
  vk::transition(cmd, chain, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  const VkClearColorValue far{{1.0f, 1.0f, 1.0f, 1.0f}};
  const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, chain.desc().mip_levels, 0, 1};
  vkCmdClearColorImage(cmd, chain.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &far, 1, &all);
  vk::between_transfer_writes(cmd, chain);
  for (std::size_t m = 0; m < levels.size(); ++m) {
    const vk::Image& level = levels[m];
    vk::transition(cmd, level, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                   VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    VkImageCopy copy{};
    copy.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, static_cast<std::uint32_t>(m), 0, 1};
    copy.extent = {level.desc().width, level.desc().height, 1};
    vkCmdCopyImage(cmd, level.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, chain.get(),
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
  }
  vk::transition(cmd, chain, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kMinmaxLayout);
}

}  // namespace

Result<MinmaxBuild> build_minmax(Context& context, ShadowMapImages& map, const PassProgram& init,
                                 const PassProgram& reduce, const ParamBlock& params) {
  const VkExtent2D map_size = map.colour.extent();
  const int width = static_cast<int>(map_size.width);
  const int height = static_cast<int>(map_size.height);
  std::vector<LevelSize> sizes = minmax_level_sizes(width, height);
  const int top = static_cast<int>(sizes.size());
  MinmaxBuild build;
  build.levels = top;
  std::vector<vk::Image> levels;
  LevelSize source{width, height};
  for (int level = 1; level <= top; ++level) {
    const LevelSize size = sizes[static_cast<std::size_t>(level - 1)];
    auto target = create_level_target(context, size, level);
    if (!target) return target.error();
    // Each pass reads the level below (source_size) and finds its own texel
    // from its target's size (screen_size); everything else as given.
    ParamBlock level_params = params;
    level_params["source_size"] = size_vec4(source.width, source.height);
    level_params["screen_size"] = size_vec4(size.width, size.height);

    PassDraw draw;
    draw.program = level == 1 ? &init : &reduce;
    draw.shape = {level == 1 ? "minmax_init pass" : "minmax_reduce pass",
                  kMinmaxTarget,
                  kQueryPositionFormat,
                  2,
                  false,
                  false};
    draw.resources.params = &level_params;
    if (level == 1) {
      // The map's depth only, as the GL engine offers it (docs/runtime.md).
      draw.resources.offer_map(map, /*comparison=*/false);
    } else {
      draw.resources.offer(TextureId::minmax_source, levels.back(),
                           VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    }
    draw.positions = kFullScreenTriangle;
    // Read next by the following reduce pass and by the copy into the chain.
    draw.target = sampled_target(*target);
    auto elapsed = draw_pass(context, draw);
    if (!elapsed) return elapsed.error();
    add_gpu_time(build.gpu_ms, *elapsed);
    levels.push_back(std::move(*target));
    source = size;
  }

  auto chain = create_chain(context, width, height);
  if (!chain) return chain.error();
  PENUMBRA_TRY(context.commands->submit(
      [&](VkCommandBuffer cmd) { record_chain_copies(cmd, *chain, levels); },
      "the copies into the min-max mip"));
  map.minmax = MinmaxMip{std::move(*chain), std::move(sizes)};
  return build;
}

Result<std::vector<FloatImage>> read_minmax(Context& context, const ShadowMapImages& map) {
  if (!map.minmax) {
    return make_error(Error::Kind::bad_input, "shadow map",
                      "has no min-max mip to read; build it with Engine::build_minmax first");
  }
  std::vector<FloatImage> levels;
  for (std::size_t m = 0; m < map.minmax->sizes.size(); ++m) {
    const LevelSize size = map.minmax->sizes[m];
    const VkExtent2D extent{static_cast<std::uint32_t>(size.width),
                            static_cast<std::uint32_t>(size.height)};
    auto texels = read_image_region(*context.device, *context.commands, map.minmax->image,
                                    kMinmaxLayout, static_cast<std::uint32_t>(m), extent, 2,
                                    "min-max level " + std::to_string(m + 1));
    if (!texels) return texels.error();
    FloatImage level(size.width, size.height, 2);
    level.data = std::move(*texels);
    levels.push_back(std::move(level));
  }
  return levels;
}

}  // namespace penumbra::detail
