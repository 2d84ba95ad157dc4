// Moving float texels between the host and an image through staging buffers.
#pragma once

#include <vulkan/vulkan.h>

#include <span>
#include <string_view>
#include <vector>

#include "penumbra/support/result.hpp"
#include "vk/command_context.hpp"
#include "vk/device.hpp"
#include "vk/image.hpp"

namespace penumbra::detail {

// Copies `texels` (tightly packed 32-bit floats, row 0 first, layer after
// layer, exactly the image's size) into `image`, whose old contents are discarded, and leaves it
// in `final_layout`. `what` names the image in errors.
Status upload_image(const vk::Device& device, vk::CommandContext& commands, const vk::Image& image,
                    std::span<const float> texels, VkImageLayout final_layout,
                    std::string_view what);

// Reads `image`'s level 0, which is in `layout` and is left in it, as
// `components` floats per texel, row 0 first, layer after layer.
Result<std::vector<float>> read_image(const vk::Device& device, vk::CommandContext& commands,
                                      const vk::Image& image, VkImageLayout layout,
                                      std::uint32_t components, std::string_view what);

// A depth image's level 0 (D32_SFLOAT, X8_D24_UNORM_PACK32 or D16_UNORM),
// in `layout` and left in it, as the floats its sampler returns.
Result<std::vector<float>> read_depth_image(const vk::Device& device, vk::CommandContext& commands,
                                            const vk::Image& image, VkImageLayout layout,
                                            std::string_view what);

// The same for the texels [0, extent) of mip level `level`.
Result<std::vector<float>> read_image_region(const vk::Device& device, vk::CommandContext& commands,
                                             const vk::Image& image, VkImageLayout layout,
                                             std::uint32_t level, VkExtent2D extent,
                                             std::uint32_t components, std::string_view what);

}  // namespace penumbra::detail
