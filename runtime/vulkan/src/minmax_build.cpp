#include "minmax_build.hpp"

#include <string>
#include <utility>
#include <vector>

#include "formats.hpp"
#include "image_transfer.hpp"
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

// The chain: padding cleared to 1.0 (the far plane, as the map's clear), each
// level copied in, then at rest for sampling.
void record_chain_copies(VkCommandBuffer cmd, const vk::Image& chain,
                         const std::vector<const vk::Image*>& levels) {
  vk::transition(cmd, chain, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  const VkClearColorValue far{{1.0f, 1.0f, 1.0f, 1.0f}};
  const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, chain.desc().mip_levels, 0, 1};
  vkCmdClearColorImage(cmd, chain.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &far, 1, &all);
  vk::between_transfer_writes(cmd, chain);
  for (std::size_t m = 0; m < levels.size(); ++m) {
    const vk::Image& level = *levels[m];
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

Result<MinmaxMip> gather_minmax(Context& context, int width, int height,
                                const std::vector<const vk::Image*>& levels) {
  std::vector<LevelSize> sizes = minmax_level_sizes(width, height);
  if (levels.size() != sizes.size()) {
    return make_error(Error::Kind::internal, "the min-max mip",
                      std::to_string(levels.size()) + " levels drawn for a " +
                          std::to_string(width) + "x" + std::to_string(height) + " map of " +
                          std::to_string(sizes.size()));
  }
  auto chain = create_chain(context, width, height);
  if (!chain) return chain.error();
  PENUMBRA_TRY(context.commands->submit(
      [&](VkCommandBuffer cmd) { record_chain_copies(cmd, *chain, levels); },
      "the copies into the min-max mip"));
  return MinmaxMip{std::move(*chain), std::move(sizes)};
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
